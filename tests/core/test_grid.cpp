// The periodic grid: index helpers and the wavenumbers of the r2c spectrum.
#include <gtest/gtest.h>

#include <numbers>

#include "wearscale/core/field.hpp"

using wearscale::Grid2D;

TEST(Grid2D, SpacingAndAreaFollowFromSizeAndPoints) {
  const Grid2D g(8, 4, 2.0, 1.0);
  EXPECT_DOUBLE_EQ(g.dx(), 0.25);
  EXPECT_DOUBLE_EQ(g.dy(), 0.25);
  EXPECT_DOUBLE_EQ(g.area(), 2.0);
  EXPECT_EQ(g.size(), 32u);
  EXPECT_EQ(g.spectral_ny(), 3u);
}

TEST(Grid2D, IndicesWrapPeriodically) {
  const Grid2D g(8, 4, 1.0, 1.0);
  EXPECT_EQ(g.wrap_x(-1), 7u);
  EXPECT_EQ(g.wrap_x(8), 0u);
  EXPECT_EQ(g.wrap_x(-17), 7u);
  EXPECT_EQ(g.wrap_y(5), 1u);
  EXPECT_EQ(g.periodic_index(-1, -1), g.index(7, 3));
}

TEST(Grid2D, SpectralFrequenciesAreSignedAlongX) {
  const Grid2D g(8, 8, 2.0, 2.0);
  EXPECT_EQ(g.frequency_x(0), 0);
  EXPECT_EQ(g.frequency_x(4), 4);   // Nyquist
  EXPECT_EQ(g.frequency_x(5), -3);
  EXPECT_EQ(g.frequency_x(7), -1);
  EXPECT_DOUBLE_EQ(g.wavenumber_x(1), 2.0 * std::numbers::pi / 2.0);  // q = 2πk/L
  EXPECT_DOUBLE_EQ(g.wavenumber_y(3), 3.0 * std::numbers::pi);
}

TEST(Field2D, PeriodicAccessReadsTheImagePoint) {
  wearscale::RealField f(Grid2D(4, 4, 1.0, 1.0));
  f(3, 0) = 7.0;
  EXPECT_EQ(f.periodic(-1, 4), 7.0);
  EXPECT_EQ(f.size(), 16u);
  EXPECT_EQ(wearscale::ComplexField::spectrum_of(f.grid()).size(), 4u * 3u);
}
