// `wearscale dem`: the patch test prints measured E, ν beside the targets;
// the sheared junction writes its force history, snapshots and a verdict;
// bad input → status 2 naming the key and the allowed range.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_dem_cli_");
const std::filesystem::path work = work_scratch.path();
}  // namespace

TEST(DemCli, PatchTestReportsElasticConstantsBesideTargets) {
  fs::create_directories(work);
  const auto r = run_cli("dem patch-test --lattice hcp --nu 0.1 --length 12 --no-strengths --out pt --json", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["results"]["young"]["value"].get<double>(), 1.0, 0.12);
  EXPECT_NEAR(j["results"]["poisson"]["value"].get<double>(), 0.1, 0.012);
  EXPECT_THAT(j["results"]["poisson"]["description"].get<std::string>(), HasSubstr("target 0.1"));
  EXPECT_TRUE(fs::exists(work / "pt" / "patch_test.csv"));
  EXPECT_TRUE(fs::exists(work / "pt" / "summary.json"));
}

TEST(DemCli, JunctionWritesHistorySnapshotsAndVerdict) {
  fs::create_directories(work);
  const auto r = run_cli("dem junction --material SiO2 --D 20e-9 --d0 '6 nm' --slide '3 nm' --out jn --json", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["results"]["d_star"]["value"].get<double>(), 18.5e-9, 0.5e-9);  // (6.65)
  EXPECT_TRUE(j.contains("verdict"));
  for (const char* f : {"junction_history.csv", "junction.h5", "junction.dump", "summary.json"})
    EXPECT_TRUE(fs::exists(work / "jn" / f)) << f;
  const std::string dump = slurp(work / "jn" / "junction.dump");
  EXPECT_THAT(dump, HasSubstr("ITEM: ATOMS id type x y z radius"));
}

TEST(DemCli, BadInputNamesTheKeyAndExitsWithTwo) {
  fs::create_directories(work);
  auto r = run_cli("dem patch-test --nu 0.3 --out bad", work);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("dem.poisson"));
  EXPECT_THAT(r.err, HasSubstr("0.25"));
  r = run_cli("dem junction --material SiO2 --D 50e-9 --d0 6e-9 --out bad", work);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("D"));
  r = run_cli("dem junction --material Unobtainium --D 20e-9 --d0 6e-9 --out bad", work);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("SiO2"));
  EXPECT_FALSE(fs::exists(work / "bad" / "junction.dump"));
}

// Silent garbage is refused: a lattice whose second neighbours
// fall within the cohesive reach exits 2 with the smallest valid d0 (it
// reported ν = 2.2), a sample that never comes to rest exits 1 (it reported
// E = 0.71, ν = 0.25); neither writes a result.
TEST(DemCli, PatchTestRefusesGarbageInsteadOfReportingIt) {
  fs::create_directories(work);
  auto r = run_cli("dem patch-test --nu 0.1 --d0 70 --length 8 --no-strengths --out near --json", work);
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_THAT(r.err, HasSubstr("second neighbours"));
  EXPECT_THAT(r.err, HasSubstr("d0 ≥ 74.99"));
  EXPECT_FALSE(fs::exists(work / "near" / "summary.json"));
  r = run_cli("dem patch-test --length 8 --no-strengths --set dem.patch_test.time_step=0.4 --out hot --json", work);
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_THAT(r.err, HasSubstr("numerical failure"));
  EXPECT_FALSE(fs::exists(work / "hot" / "summary.json"));
}

// nano/dem's Si keys: `amorphous` names case materials (or "none"),
// `max_poisson` stays at most the pair force's 1/4; refused before any run.
TEST(DemCli, NanoDemRefusesUnknownAmorphousMaterialsAndPoissonAboveAQuarter) {
  fs::create_directories(work);
  const std::string si = "run '" + std::string(WEARSCALE_SOURCE_DIR) + "/cases/junction_sio2_si.toml' --out bad_si";
  auto r = run_cli(si + " --set scale.nano.amorphous=Unobtainium", work);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("scale.nano.amorphous"));
  EXPECT_THAT(r.err, HasSubstr("no material 'Unobtainium'"));
  r = run_cli(si + " --set scale.nano.max_poisson=0.3", work);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("scale.nano.max_poisson"));
  EXPECT_THAT(r.err, HasSubstr("(-1, 0.25]"));
  EXPECT_FALSE(fs::exists(work / "bad_si" / "summary.json"));
}
