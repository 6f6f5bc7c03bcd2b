// The [md] case keys of the §9.3.1 shear test, read into md::ShearTestSpec
// (moved from tests/md with the reader: the md library reads no case).
#include <gtest/gtest.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/coupling/shear_test_keys.hpp"
#include "wearscale/io/config.hpp"

using namespace wearscale;
using namespace wearscale::md;
using wearscale::coupling::read_shear_test_spec;

TEST(ShearConfig, KeysOverrideThePresetWithUnits) {
  Config c = Config::from_string(R"(
[md]
material = "Si"
preset = "smoke"
pressures = ["0 GPa", 1e10, "25 GPa"]
shear_velocity = "10 m/s"
window = [0.45, 0.6]
seed = 7
)");
  const ShearTestSpec s = read_shear_test_spec(c);
  ASSERT_EQ(s.pressures.size(), 3u);
  EXPECT_DOUBLE_EQ(s.pressures[2], 25e9);
  EXPECT_DOUBLE_EQ(s.shear_velocity, 10.0);
  EXPECT_DOUBLE_EQ(s.window_begin, 0.45);
  EXPECT_EQ(s.seed, 7u);
  EXPECT_NO_THROW(c.reject_unknown_keys());
}

TEST(ShearConfig, BadValuesAreInputErrors) {
  auto read = [](const std::string& body) { return read_shear_test_spec(Config::from_string("[md]\n" + body)); };
  EXPECT_THROW(read("material = \"Cu\"\npressures = [0]"), InputError);
  EXPECT_THROW(read("material = \"Si\"\npressures = [\"10 m/s\"]"), InputError);
  EXPECT_THROW(read("material = \"Si\"\npressures = [10e9, 0]"), InputError);
  EXPECT_THROW(read("material = \"Si\"\npressures = [0, 1e9]\nwindow = [0.5, 0.9]"), InputError);
  EXPECT_THROW(read("material = \"Si\"\npressures = [0, 1e9]\ncutoff = \"8 Å\""), InputError);
  EXPECT_THROW(read("material = \"Si\"\npressures = [0, 1e9]\nheight = \"1 nm\""), InputError);
}

TEST(ShearConfig, QuenchKeysWithUnits) {
  Config c = Config::from_string(R"(
[md]
material = "SiO2"
pressures = [0, "50 GPa"]
cutoff = "8 Å"
[md.quench]
temperatures = [5000, 2000, 300]
hold_time = "45 ps"
cooling_rate = "166 K/ps"
final_cooling_rate = "13 K/ps"
timestep = "0.0005 ps"
)");
  const ShearTestSpec s = read_shear_test_spec(c);
  EXPECT_DOUBLE_EQ(s.cutoff, 8e-10);
  ASSERT_EQ(s.quench.temperatures.size(), 3u);
  EXPECT_NEAR(s.quench.cooling_rate, 166e12, 1e3);
  EXPECT_NEAR(s.quench.final_cooling_rate, 13e12, 1e3);
  EXPECT_NEAR(s.quench.timestep, 0.5e-15, 1e-25);
  EXPECT_NEAR(s.quench.hold_time, 45e-12, 1e-22);
  EXPECT_NO_THROW(c.reject_unknown_keys());
  Config si = Config::from_string("[md]\nmaterial = \"Si\"\npressures = [0, 1e9]\n[md.quench]\nhold_time = 1\n");
  EXPECT_THROW(read_shear_test_spec(si), InputError);
}
