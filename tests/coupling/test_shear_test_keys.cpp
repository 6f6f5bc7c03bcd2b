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
  EXPECT_DOUBLE_EQ(s.model.cutoff, 8e-10);
  ASSERT_EQ(s.quench.temperatures.size(), 3u);
  EXPECT_NEAR(s.quench.cooling_rate, 166e12, 1e3);
  EXPECT_NEAR(s.quench.final_cooling_rate, 13e12, 1e3);
  EXPECT_NEAR(s.quench.timestep, 0.5e-15, 1e-25);
  EXPECT_NEAR(s.quench.hold_time, 45e-12, 1e-22);
  EXPECT_NO_THROW(c.reject_unknown_keys());
  Config si = Config::from_string("[md]\nmaterial = \"Si\"\npressures = [0, 1e9]\n[md.quench]\nhold_time = 1\n");
  EXPECT_THROW(read_shear_test_spec(si), InputError);
}

TEST(ShearConfig, AMaterialTheCaseDefinesWithItsInteratomicModel) {
  Config c = Config::from_string(R"(
[materials.define.Ni]
young = "200 GPa"
poisson = 0.31
density = "8.9 g/cm^3"
surface_energy = "2.2 J/m^2"
tensile_strength = "20 GPa"
shear_strength = "5 GPa"
[materials.define.Ni.interatomic]
pair_style = "eam"
potential = "Ni_u3.eam"
elements = ["Ni"]
masses = [58.6934]
structure = "fcc"
lattice_constant = "3.52 Å"
[md]
material = "Ni"
pressures = [0, "5 GPa"]
)", "ni.toml");
  const ShearTestSpec s = read_shear_test_spec(c);
  EXPECT_EQ(s.material, "Ni");
  EXPECT_EQ(s.model.pair_style, "eam");
  EXPECT_EQ(s.model.potential, "Ni_u3.eam") << "a bare name not beside the case: LAMMPS' potentials folder";
  EXPECT_DOUBLE_EQ(s.model.lattice_constant, 3.52e-10);
  EXPECT_EQ(s.lateral_cells(), 6);
  EXPECT_NO_THROW(c.reject_unknown_keys());
  // A material without an interatomic model, a quench for a crystal, a cutoff for eam: refused by key.
  Config plain = Config::from_string("[materials.define.Y]\nyoung = 1\npoisson = 0.3\ndensity = 1\nsurface_energy = 1\n"
                                     "tensile_strength = 1\nshear_strength = 1\n[md]\nmaterial = \"Y\"\npressures = [0]\n");
  try {
    read_shear_test_spec(plain);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("interatomic"), std::string::npos) << e.what();
  }
  Config q = c;
  q.override_value("md.quench.hold_time=1e-12");
  EXPECT_THROW(read_shear_test_spec(q), InputError);
  Config cut = c;
  cut.override_value("md.cutoff=8e-10");
  EXPECT_THROW(read_shear_test_spec(cut), InputError);
}

TEST(ShearConfig, ATableNamedAfterAMaterialHoldsKeysForItAlone) {
  Config c = Config::from_string(R"(
[scale.molecular]
pressures = ["0 GPa", "10 GPa"]
strain_end = 0.6
[scale.molecular.SiO2]
pressures = ["0 GPa", "50 GPa"]
strain_end = 0.8
window = [0.6, 0.8]
)");
  const Config m = c.section("scale.molecular");
  const ShearTestSpec si = read_shear_test_spec(m, "Si", materials::silicon_model());
  const ShearTestSpec sio2 = read_shear_test_spec(m, "SiO2", materials::silica_model());
  EXPECT_EQ(si.pressures, (std::vector<double>{0.0, 10e9}));
  EXPECT_DOUBLE_EQ(si.strain_end, 0.6);
  EXPECT_EQ(sio2.pressures, (std::vector<double>{0.0, 50e9}));
  EXPECT_DOUBLE_EQ(sio2.strain_end, 0.8);
  EXPECT_DOUBLE_EQ(sio2.window_begin, 0.6);
  EXPECT_NO_THROW(c.reject_unknown_keys());
}
