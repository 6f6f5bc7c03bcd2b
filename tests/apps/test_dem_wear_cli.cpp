// `wearscale dem rough-shear|trapped-particles` (thesis §7.2-7.3): bad input →
// status 2 naming the file, the key, the value and the allowed range, and no
// output written. (The runs themselves are the case regressions of
// cases/dem_rough_shear.toml and cases/dem_trapped_particles.toml.)
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>

#include "cli_runner.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_dem_wear_cli_");
const std::filesystem::path work = work_scratch.path();
const std::string source = WEARSCALE_SOURCE_DIR;
}  // namespace

TEST(DemWearCli, RoughShearRefusesBadKeysWithTheAllowedRange) {
  fs::create_directories(work);
  const std::string rough = "dem rough-shear '" + source + "/cases/dem_rough_shear.toml' --out bad_rs";
  {
    std::ofstream bad(work / "too_rough.toml");
    bad << "[dem]\nmaterial = \"SiO2\"\n[dem.rough_shear]\nd0 = \"3 nm\"\nroughness = 0.5\n";
  }
  auto r = run_cli("dem rough-shear too_rough.toml --out bad_rs", work);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("too_rough.toml"));
  EXPECT_THAT(r.err, HasSubstr("dem.rough_shear.roughness"));
  EXPECT_THAT(r.err, HasSubstr("0.5"));
  EXPECT_THAT(r.err, HasSubstr("[0, 0.1]"));
  r = run_cli(rough + " --set 'dem.rough_shear.depth=\"3 nm\"'", work);  // < d_l = 3.75 nm, the largest particle
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("dem.rough_shear.depth"));
  r = run_cli(rough + " --set dem.rough_shear.hurts=0.7", work);  // a typo is not a default
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("hurst"));
  EXPECT_FALSE(fs::exists(work / "bad_rs" / "rough_shear.dump"));
  EXPECT_FALSE(fs::exists(work / "bad_rs" / "rough_shear_history.csv"));
}

TEST(DemWearCli, TrappedParticlesRefusesParticlesThatDoNotFit) {
  fs::create_directories(work);
  const std::string trapped = "dem trapped-particles '" + source + "/cases/dem_trapped_particles.toml' --out bad_tp";
  auto r = run_cli(trapped + " --n 12", work);  // 12 (D + d0) = 396 nm > L = 300 nm
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("dem.trapped_particles.length"));
  r = run_cli(trapped + " --n 0", work);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("dem.trapped_particles.count"));
  r = run_cli(trapped + " --D '6 nm'", work);  // < 3 d0
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("dem.trapped_particles.diameter"));
  r = run_cli(trapped + " --pressure '20 GPa'", work);  // above σ_m,N
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("dem.trapped_particles.pressure"));
  EXPECT_FALSE(fs::exists(work / "bad_tp" / "trapped_particles.dump"));
  fs::remove_all(work);
}

TEST(DemWearCli, TheContactLawKeyNamesARegisteredLawAndTheStrengthStudiesRefuseHooke) {
  fs::create_directories(work);
  const std::string rough = "dem rough-shear '" + source + "/cases/dem_rough_shear.toml' --out bad_law";
  auto r = run_cli(rough + " --set 'dem.law=\"hertz\"'", work);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("dem.law"));
  EXPECT_THAT(r.err, HasSubstr("hertz"));
  EXPECT_THAT(r.err, HasSubstr("cohesive, "));  // the registered laws, in name order
  r = run_cli(rough + " --set dem.friction=0.3", work);  // μ belongs to the hooke law only
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("friction"));
  r = run_cli("dem patch-test '" + source + "/cases/dem_patch_test.toml' --out bad_law --set 'dem.law=\"hooke\"'", work);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("dem.law"));
  EXPECT_THAT(r.err, HasSubstr("cohesive law's strengths"));
  EXPECT_FALSE(fs::exists(work / "bad_law" / "rough_shear_history.csv"));
}

TEST(DemWearCli, TheHistoryTransferIsKeptOrTouchingOnTheSlidingCellsOnly) {
  fs::create_directories(work);
  const std::string rough = "dem rough-shear '" + source + "/cases/dem_rough_shear.toml' --out bad_history";
  auto r = run_cli(rough + " --set 'dem.history=\"lammps\"'", work);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("dem.history"));
  EXPECT_THAT(r.err, HasSubstr("lammps"));
  EXPECT_THAT(r.err, HasSubstr("kept"));
  EXPECT_THAT(r.err, HasSubstr("touching"));
  // The studies that measure the law's strengths do not read it: an unknown key.
  r = run_cli("dem patch-test '" + source + "/cases/dem_patch_test.toml' --out bad_history --set 'dem.history=\"touching\"'",
              work);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("history"));
  EXPECT_FALSE(fs::exists(work / "bad_history" / "rough_shear_history.csv"));
}
