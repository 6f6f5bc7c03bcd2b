// Materials a case defines ([materials.define.<name>]): read with units,
// range-checked, and added beside the built-in ones.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/io/config.hpp"
#include "wearscale/io/material_definitions.hpp"

using namespace wearscale;
using namespace wearscale::materials;

TEST(MaterialLibrary, CaseDefinedMaterialsAreReadWithUnitsAndChecked) {
  auto cfg = Config::from_string(R"(
[materials.define.Al2O3]
young = "400 GPa"
poisson = 0.22
density = "3.95 g/cm^3"
surface_energy = "1 J/m^2"
tensile_strength = "30 GPa"
shear_strength = "20 GPa"
)", "alumina.toml");
  MaterialLibrary lib;
  define_materials_from(lib, cfg);
  EXPECT_DOUBLE_EQ(lib.get("Al2O3").young, 400e9);
  EXPECT_NEAR(lib.get("Al2O3").density, 3950.0, 1e-9);
  EXPECT_FALSE(lib.get("Al2O3").restitution.has_value());
  EXPECT_EQ(lib.get("Si").young, 150e9);
  EXPECT_NO_THROW(cfg.reject_unknown_keys());
}

TEST(MaterialLibrary, BadDefinitionsAndUnknownNamesAreBadInput) {
  auto cfg = Config::from_string("[materials.define.X]\nyoung = -1\n", "x.toml");
  MaterialLibrary lib;
  try {
    define_materials_from(lib, cfg);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("materials.define.X.young"));
  }
  try {
    lib.get("Cu");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("Si, SiO2"));
  }
}
