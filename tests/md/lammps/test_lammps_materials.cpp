// Any material with a LAMMPS potential, for real (label `lammps`; CI installs
// lammps and lammps-data): the finite-strain elastic constants of Mishin's
// EAM copper are the published ones; nickel (Foiles–Baskes–Daw EAM, a
// material the shipped cases do not use) run through the shear protocol on a
// tiny sample passes its elastic check and shears with the potential's shear
// modulus C44; a sample declared with a wrong lattice constant is refused before
// any shear run. About half a minute together on a free core.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scratch_dir.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/md/elastic_constants.hpp"
#include "wearscale/md/lammps_runner.hpp"
#include "wearscale/md/potential_file.hpp"
#include "wearscale/md/shear_study.hpp"

using namespace wearscale;
using namespace wearscale::md;
namespace fs = std::filesystem;

namespace {

const ScratchDir scratch("wearscale-md-materials-");

materials::InteratomicModel nickel() {
  materials::InteratomicModel m;
  m.pair_style = "eam";
  m.potential = "Ni_u3.eam";  // Foiles, Baskes & Daw 1986
  m.elements = {"Ni"};
  m.masses = {58.6934};
  m.structure = materials::Structure::Fcc;
  m.lattice_constant = 3.52e-10;
  return m;
}

}  // namespace

TEST(LammpsElastic, MishinCopperHasItsPublishedElasticConstants) {
  materials::InteratomicModel cu;
  cu.pair_style = "eam/alloy";
  cu.potential = "Cu_mishin1.eam.alloy";
  cu.elements = {"Cu"};
  cu.masses = {63.546};
  cu.structure = materials::Structure::Fcc;
  cu.lattice_constant = 3.6e-10;  // a guess: the ideal lattice is relaxed to zero stress first
  const fs::path dir = scratch.path() / "cu-elastic";
  fs::create_directories(dir);
  fs::copy_file(find_potential_file(cu.potential), dir / "Cu_mishin1.eam.alloy");
  ElasticDeckFiles files;
  files.potential = "Cu_mishin1.eam.alloy";
  std::ofstream(dir / "in.lammps") << elastic_deck(cu, {3, 3, {}, true}, files, 1e-3, "test");
  run_lammps({find_lmp(), 1, dir, "in.lammps", "Cu elastic constants"});
  const ElasticResult r = parse_elastic(read_text_file(dir / "elastic.txt"), 1e-3, "elastic.txt");
  // Mishin et al., Phys. Rev. B 63, 224106 (2001), Table I: a0 = 3.615 Å, C11 = 169.9, C12 = 122.6, C44 = 76.2 GPa.
  EXPECT_NEAR(r.lx / 3, 3.615e-10, 0.001e-10);
  EXPECT_NEAR(r.c[0][0], 169.9e9, 0.005 * 169.9e9);
  EXPECT_NEAR(r.c[2][2], 169.9e9, 0.005 * 169.9e9);
  EXPECT_NEAR(r.c[0][1], 122.6e9, 0.005 * 122.6e9);
  EXPECT_NEAR(r.c[3][3], 76.2e9, 0.005 * 76.2e9);
  EXPECT_NEAR(r.c[5][5], 76.2e9, 0.005 * 76.2e9);
  EXPECT_NEAR(r.c[0][3], 0.0, 0.1e9) << "cubic: no normal-shear coupling";
}

TEST(LammpsShearProtocol, NickelShearsWithThePotentialsShearModulus) {
  ShearTestSpec s = preset_spec("Ni", nickel(), "smoke");
  // Tiny and short: 6 × 6 × 6 cells (936 atoms), the elastic start only (strain 0.05).
  // At 1 K, so that the shear test's modulus is C44 at 0 K, the potential's; at
  // 20 m/s, so that the elastic wave the moving wall sends (ρ c_t v ≈ 0.6 GPa) stays
  // small against G γ; fitted over strains up to 0.03, where C44 softens by ~1 %.
  s.pressures = {0.0};
  s.temperature = 1.0;
  s.shear_velocity = 20.0;
  s.compression_time = 1e-12;
  s.strain_end = 0.05;
  s.window_begin = 0.04;
  s.window_end = 0.05;
  s.modulus_strain = 0.03;
  s.cache_dir = scratch.path() / "ni-cache";
  const ShearStudy study = run_shear_study(s);
  ASSERT_TRUE(study.elastic.has_value());
  const ElasticCheck& e = *study.elastic;
  EXPECT_TRUE(e.passed()) << e.summary();
  // The sample is the ideal lattice at the potential's own lattice constant: the same moduli.
  EXPECT_NEAR(e.reference_lattice_constant, 3.52e-10, 0.002e-10);
  EXPECT_LT(e.young_error, 0.01);
  EXPECT_LT(std::abs(e.sample_pressure), 0.1e9);
  ASSERT_EQ(study.points.size(), 1u);
  const ShearPoint& p = study.points[0];
  EXPECT_EQ(p.atoms, 936);
  // The shear test's own elastic start (τ on the top wall over the strain of the gap between the
  // walls) against the potential's C44 (G_xz of the reference, 127.6 GPa): within 3 %, the
  // softening over the fitted strains and the wall's elastic waves (measured: 1.6 % below).
  EXPECT_NEAR(p.shear_modulus, e.reference.shear_xz, 0.03 * e.reference.shear_xz)
      << "G from the shear curve " << p.shear_modulus / 1e9 << " GPa, C44 " << e.reference.shear_xz / 1e9 << " GPa";
}

TEST(LammpsShearProtocol, ASampleDeclaredWithAWrongLatticeConstantIsRefusedBeforeShearing) {
  materials::InteratomicModel m = nickel();
  m.lattice_constant = 3.40e-10;  // 3.4 % short of the potential's 3.52 Å: a sample under ~20 GPa of pressure
  ShearTestSpec s = preset_spec("Ni", m, "smoke");
  s.pressures = {0.0};
  s.cache_dir = scratch.path() / "ni-wrong";
  try {
    (void)run_shear_study(s);
    FAIL() << "no refusal";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("the MD sample is refused"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("3.5200 A against the declared 3.4000 A"));
  }
  // No shear run was made: only the two elastic-constant runs are in the cache.
  std::size_t entries = 0;
  for (const auto& d : fs::directory_iterator(s.cache_dir))
    if (d.is_directory() && d.path().filename().string().size() == 64) ++entries;
  EXPECT_EQ(entries, 2u);
}
