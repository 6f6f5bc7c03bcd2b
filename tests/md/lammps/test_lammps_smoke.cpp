// The real thing, with LAMMPS (label `lammps`; CI installs the Debian package):
// the Si smoke preset at two pressures, run with lmp (a fresh cache, so it
// really runs), gives a peak above the dynamic strength above zero, and a
// table in the shipped format that reads back.
#include <gtest/gtest.h>

#include <unistd.h>

#include "wearscale/io/strength_table_file.hpp"
#include "wearscale/materials/strength_table.hpp"
#include "wearscale/md/shear_study.hpp"
#include "scratch_dir.hpp"

using namespace wearscale;
using namespace wearscale::md;

TEST(LammpsSmoke, SiAtTwoPressuresGivesAPhysicalStrength) {
  static const ScratchDir dir_scratch("wearscale-md-lammps-");
  const std::filesystem::path dir = dir_scratch.path();
  std::filesystem::remove_all(dir);
  ShearTestSpec s = preset_spec("Si", "smoke");
  s.pressures = {0.0, 10e9};
  s.cache_dir = dir / "cache";
  const ShearStudy study = run_shear_study(s);  // InputError (apt-get install lammps) if lmp is missing
  ASSERT_EQ(study.points.size(), 2u);
  for (const auto& p : study.points) {
    EXPECT_FALSE(p.run.cached);
    EXPECT_GT(p.strength.sigma_max, p.strength.sigma_dyn) << p.pressure;
    EXPECT_GT(p.strength.sigma_dyn, 0.0) << p.pressure;
    // Physical sanity, wide bands (thesis: ~11 GPa peak for crystalline Si).
    EXPECT_GT(p.strength.sigma_max, 5e9) << p.pressure;
    EXPECT_LT(p.strength.sigma_max, 20e9) << p.pressure;
    EXPECT_TRUE(p.strength.failed_before_window) << p.pressure;
    EXPECT_NEAR(p.strength.normal_stress, p.pressure, 1e9) << "the imposed load is the measured one";
    EXPECT_EQ(p.atoms, 544);
  }
  const auto file = dir / "lammps_smoke_Si.csv";
  materials::write_strength_table(file, strength_table(study));
  const materials::StrengthTable back = materials::read_strength_table(file);
  EXPECT_EQ(back.material, "Si");
  ASSERT_EQ(back.pressure.size(), 2u);
  EXPECT_NEAR(back.pressure[1], 10e9, 1e3);
  EXPECT_NEAR(back.sigma_max[0], study.points[0].strength.sigma_max, 1e-6 * study.points[0].strength.sigma_max);
  EXPECT_EQ(back.info("lammps_version"), study.lammps_version);
  std::filesystem::remove_all(dir);
}
