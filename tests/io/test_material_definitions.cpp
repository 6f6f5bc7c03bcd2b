// Materials a case defines ([materials.define.<name>]): read with units,
// range-checked, and added beside the built-in ones.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <set>

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

namespace {
const char* kCopper = R"(
[materials.define.Cu]
young = "130 GPa"
poisson = 0.34
density = "8.96 g/cm^3"
surface_energy = "1.8 J/m^2"
tensile_strength = "10 GPa"
shear_strength = "2.2 GPa"
[materials.define.Cu.interatomic]
pair_style = "eam/alloy"
potential = "Cu_mishin1.eam.alloy"
elements = ["Cu"]
masses = [63.546]
structure = "fcc"
lattice_constant = "3.615 Å"
source = "Mishin et al. 2001"
)";
}  // namespace

TEST(MaterialLibrary, AnInteratomicModelIsDeclaredBesideTheRecord) {
  auto cfg = Config::from_string(kCopper, "cu.toml");
  MaterialLibrary lib;
  define_materials_from(lib, cfg);
  ASSERT_TRUE(lib.get("Cu").interatomic.has_value());
  const auto& m = *lib.get("Cu").interatomic;
  EXPECT_EQ(m.pair_style, "eam/alloy");
  EXPECT_EQ(m.elements, std::vector<std::string>{"Cu"});
  EXPECT_EQ(m.structure, Structure::Fcc);
  EXPECT_DOUBLE_EQ(m.lattice_constant, 3.615e-10);
  EXPECT_FALSE(m.amorphous);
  EXPECT_NO_THROW(cfg.reject_unknown_keys());
  EXPECT_TRUE(lib.get("Si").interatomic.has_value()) << "built in: Stillinger-Weber Si";
  EXPECT_TRUE(lib.get("SiO2").interatomic->amorphous);
}

TEST(MaterialLibrary, InteratomicTextIsHeldToASafeGrammarAtItsKey) {
  auto refused = [](const std::string& key_value, const std::string& key) {
    auto cfg = Config::from_string(kCopper, "cu.toml");
    cfg.override_value(key_value);
    MaterialLibrary lib;
    try {
      define_materials_from(lib, cfg);
      ADD_FAILURE() << key_value << " was accepted";
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr(key)) << key_value;
    }
  };
  refused(R"(materials.define.Cu.interatomic.elements=["Cu\n"])", "elements");
  refused(R"(materials.define.Cu.interatomic.elements=["Cu $x"])", "elements");
  refused(R"(materials.define.Cu.interatomic.potential="my pot#1")", "potential");
  refused(R"(materials.define.Cu.interatomic.pair_style="eam/alloy & shell")", "pair_style");
  refused(R"(materials.define.Cu.interatomic.structure="hcp")", "structure");
  refused(R"(materials.define.Cu.interatomic.masses=[-1])", "masses");
  refused(R"(materials.define.Cu.interatomic.lattice_constant="50 Å")", "lattice_constant");
  refused(R"(materials.define.Cu.interatomic.amorphous=true)", "reference");
  refused(R"(materials.define.Cu.interatomic.elements=["Cu", "Ni"])", "elements");
}

TEST(MaterialLibrary, EveryMaterialKeyIsDeclaredOnceWithItsUnitAndMeaning) {
  std::set<std::string> seen;
  for (const auto& k : wearscale::material_keys()) {
    EXPECT_TRUE(seen.insert(k.key).second) << k.key << " declared twice";
    EXPECT_FALSE(k.doc.empty()) << k.key;
    if (k.type == "number") EXPECT_FALSE(k.unit.empty()) << k.key;
  }
  for (const char* key : {"young", "interatomic.pair_style", "interatomic.potential", "interatomic.elements",
                          "interatomic.masses", "interatomic.structure", "interatomic.lattice_constant",
                          "interatomic.amorphous"})
    EXPECT_EQ(seen.count(key), 1u) << key;
}
