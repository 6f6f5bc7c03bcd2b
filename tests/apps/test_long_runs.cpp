// Full-length physics runs (label `long`, on demand: ctest -L long). CI runs
// their reduced variants (tests/cases/*.gold.json, tests/tribometer).
#include <gtest/gtest.h>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;

TEST(LongRuns, OxideThicknessSweepFollowsFig921) {
  // The thesis sweep at full length (0.5 m): bare Si at μ_Si, bulk at μ_SiO2,
  // thicker oxide → later transition, higher mean μ, less disc wear.
  static const ScratchDir work_scratch("wearscale_long_");
  const std::filesystem::path work = work_scratch.path();
  const auto r = run_cli("run '" + std::string(WEARSCALE_SOURCE_DIR) + "/cases/oxide_thickness_sweep.toml' --out sweep --json", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto runs = nlohmann::json::parse(r.out)["sweep"]["runs"];
  ASSERT_EQ(runs.size(), 6u);
  auto value = [&](std::size_t k, const char* name) { return runs[k]["results"][name]["value"].get<double>(); };
  EXPECT_NEAR(value(0, "mu_mean"), 0.14, 0.005);
  EXPECT_NEAR(value(5, "mu_mean"), 0.84, 0.005);
  for (std::size_t k = 1; k + 1 < runs.size(); ++k) {
    EXPECT_GT(value(k, "mu_mean"), value(k - 1, "mu_mean")) << runs[k]["value"];
    EXPECT_LT(value(k, "disc_wear"), value(k - 1, "disc_wear")) << runs[k]["value"];
    if (k > 1) {
      EXPECT_GT(value(k, "substrate_reached_at"), value(k - 1, "substrate_reached_at")) << runs[k]["value"];
    }
  }
  EXPECT_NEAR(value(2, "substrate_reached_at"), 0.03, 0.015);  // 1 µm: about s = 0.03 m (Fig. 9.20)
  fs::remove_all(work);
}

namespace {
// A demonstration pair recomputed from scratch: its MD strength tables by the
// case's own [scale.molecular.lammps] keys (a fresh LAMMPS cache), then the
// junction model on them, against the same case on the shipped tables. The
// MD of another machine or LAMMPS build follows other trajectories (sheared
// crystals are chaotic), so the comparison allows what one rerun changes.
void demonstration_reproduces_its_shipped_tables(const std::string& name, const std::string& pair, double p_rtol,
                                                 double mu_atol) {
  static const ScratchDir work_scratch("wearscale_long_demo_");
  const fs::path work = work_scratch.path() / name;
  const std::string case_file = std::string(WEARSCALE_SOURCE_DIR) + "/cases/" + name + ".toml";
  const auto shipped = run_cli("run '" + case_file + "' --out shipped --json", work);
  ASSERT_EQ(shipped.status, 0) << shipped.err;
  const auto md = run_cli("run '" + case_file + "' --set scale.molecular.backend=lammps --out md --json", work,
                          "WEARSCALE_CACHE='" + (work / "cache").string() + "'");
  ASSERT_EQ(md.status, 0) << md.err;
  const auto a = nlohmann::json::parse(shipped.out)["results"], b = nlohmann::json::parse(md.out)["results"];
  const double p_a = a["p_crit_" + pair]["value"].get<double>(), p_b = b["p_crit_" + pair]["value"].get<double>();
  EXPECT_NEAR(p_b, p_a, p_rtol * p_a);
  EXPECT_NEAR(b["mu0_" + pair]["value"].get<double>(), a["mu0_" + pair]["value"].get<double>(), mu_atol);
  fs::remove_all(work);
}
}  // namespace

TEST(LongRuns, CopperOnCopperRecomputedGivesItsShippedJunctionLaw) {
  demonstration_reproduces_its_shipped_tables("cu_on_cu", "Cu-Cu", 0.10, 0.05);
}

TEST(LongRuns, DiamondOnSiliconRecomputedGivesItsShippedJunctionLaw) {
  demonstration_reproduces_its_shipped_tables("diamond_on_si", "diamond-Si", 0.10, 0.05);
}
