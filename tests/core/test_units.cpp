// Unit strings are converted to SI with their dimension checked.
#include <gtest/gtest.h>

#include <cmath>

#include "wearscale/core/units.hpp"

using namespace wearscale::units;

TEST(Units, PrefixedLengthsConvertToMetres) {
  EXPECT_DOUBLE_EQ(parse_quantity("3 um").value, 3e-6);
  EXPECT_DOUBLE_EQ(parse_quantity("3 µm").value, 3e-6);
  EXPECT_DOUBLE_EQ(parse_quantity("2 mm").value, 2e-3);
  EXPECT_DOUBLE_EQ(parse_quantity("1.5 nm").value, 1.5e-9);
  EXPECT_DOUBLE_EQ(parse_quantity("4 Å").value, 4e-10);
  EXPECT_EQ(parse_quantity("3 um").dimension, length);
}

TEST(Units, CompoundUnitsCarryTheirDimension) {
  const auto v = parse_quantity("8 mm/s");
  EXPECT_DOUBLE_EQ(v.value, 8e-3);
  EXPECT_EQ(v.dimension, velocity);
  const auto rho = parse_quantity("2.2 g/cm^3");
  EXPECT_NEAR(rho.value, 2200.0, 1e-9);
  EXPECT_EQ(rho.dimension, density);
  const auto gamma = parse_quantity("1.5 J/m^2");
  EXPECT_EQ(gamma.dimension, surface_energy);
  EXPECT_EQ(parse_quantity("1.5 N/m").dimension, surface_energy);
}

TEST(Units, PressuresInGigapascal) {
  EXPECT_DOUBLE_EQ(parse_quantity("73 GPa").value, 73e9);
  EXPECT_EQ(parse_quantity("73 GPa").dimension, pressure);
  EXPECT_DOUBLE_EQ(parse_quantity("100 MPa").value, 1e8);
  EXPECT_EQ(parse_quantity("1 N/m^2").dimension, pressure);
}

TEST(Units, BareNumbersAreDimensionless) {
  EXPECT_EQ(parse_quantity("0.17").dimension, dimensionless);
  EXPECT_TRUE(std::isinf(parse_quantity("inf").value));
}

TEST(Units, UnknownUnitsAndGarbageAreRejected) {
  EXPECT_THROW(parse_quantity("3 furlongs"), std::invalid_argument);
  EXPECT_THROW(parse_quantity("fast"), std::invalid_argument);
  EXPECT_THROW(parse_quantity("3 m/"), std::invalid_argument);
  EXPECT_THROW(parse_quantity("3 m^x"), std::invalid_argument);
}

TEST(Units, DimensionsPrintReadably) {
  EXPECT_EQ(pressure.to_string(), "Pa");
  EXPECT_EQ(velocity.to_string(), "m/s");
  EXPECT_EQ(dimensionless.to_string(), "1");
  EXPECT_EQ((length * length).to_string(), "m^2");
}

TEST(Units, HugeExponentsAndOverflowsAreRejected) {
  // Found by fuzzing the topography reader ("# lx = 2 nm*Pa^1553714283"): the
  // dimension exponents overflowed (undefined behaviour) instead of an error.
  EXPECT_THROW(parse_quantity("2 Pa^1553714283"), std::invalid_argument);
  EXPECT_THROW(parse_quantity("2 m^-2147483648"), std::invalid_argument);
  EXPECT_THROW(parse_quantity("1e300 km^12"), std::invalid_argument);  // overflows in SI
  EXPECT_EQ(parse_quantity("2 m^12").dimension, length.pow(12));
}
