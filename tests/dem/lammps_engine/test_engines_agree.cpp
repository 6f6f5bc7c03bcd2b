// The drivers on both engines (reduced sizes): the LAMMPS engine measures
// what wearscale's own does. The patch test's sample comes to rest, so its
// E and ν agree closely; sliding runs are chaotic, so their aggregates do.
#include <gtest/gtest.h>

#include <cmath>

#include "wearscale/dem/lammps_engine.hpp"
#include "wearscale/dem/patch_test.hpp"

using namespace wearscale::dem;

namespace {

class EnginesAgree : public testing::Test {
 protected:
  void SetUp() override { register_lammps_engine(); }
};

PatchTestSpec table_6_4_patch(const std::string& engine) {
  PatchTestSpec s;
  s.material = patch_test_targets();
  s.material.poisson = 0.1;
  s.d0 = 90.0;
  s.length = 15.0;
  s.strengths = false;
  s.engine = engine;
  return s;
}

}  // namespace

TEST_F(EnginesAgree, PatchTestYoungsModulusAndPoissonsRatioWithinOnePercent) {
  const auto house = run_patch_test(table_6_4_patch("wearscale"));
  const auto lmp = run_patch_test(table_6_4_patch("lammps"));
  ASSERT_TRUE(house.elastic_converged);
  ASSERT_TRUE(lmp.elastic_converged);
  EXPECT_EQ(lmp.particles, house.particles);
  EXPECT_NEAR(lmp.young, house.young, 0.01 * house.young);
  EXPECT_NEAR(lmp.poisson, house.poisson, 0.01 * house.poisson);
  RecordProperty("young_wearscale", std::to_string(house.young));
  RecordProperty("young_lammps", std::to_string(lmp.young));
  RecordProperty("poisson_wearscale", std::to_string(house.poisson));
  RecordProperty("poisson_lammps", std::to_string(lmp.poisson));
  std::printf("E %.6f / %.6f, nu %.6f / %.6f, steps %ld / %ld\n", house.young, lmp.young, house.poisson, lmp.poisson,
              house.elastic_steps, lmp.elastic_steps);
}

#include <chrono>
#include <cstdlib>
#include "wearscale/dem/junction_strength.hpp"
#include "wearscale/materials/material.hpp"

TEST_F(EnginesAgree, ExploreFullContact) {
  const char* v = std::getenv("EXPLORE_V");
  if (v == nullptr) GTEST_SKIP();
  const bool only_touching = std::getenv("EXPLORE_TOUCHING") != nullptr;
  for (const char* engine : {"wearscale", "lammps"})
    for (bool touching : {false, true}) {
      if (only_touching && !touching) continue;
      JunctionStrengthSpec s;
      s.top = s.bottom = cohesive_material(wearscale::materials::silica(), 0.5);
      s.cell.d0 = 1.5e-9;
      s.contact_ratio = 1.0;
      s.velocity = std::atof(v);
      s.sliding_distance = std::atof(std::getenv("EXPLORE_SLIDE"));
      s.history_of_touching_pairs_only = touching;
      s.engine = engine;
      if (std::getenv("EXPLORE_EVERY")) s.record_every = std::atol(std::getenv("EXPLORE_EVERY"));
      const auto t0 = std::chrono::steady_clock::now();
      const auto r = run_junction_strength(s);
      const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::printf("%s touching=%d: peak %.4f GPa steady %.4f GPa, %ld steps, %zu particles, %.1f s\n", engine, touching,
                  r.peak_tangential / 1e9, r.steady_tangential / 1e9, r.steps, r.particles, sec);
      std::fflush(stdout);
      if (std::getenv("EXPLORE_DUMP")) {
        FILE* f = std::fopen((std::string("/tmp/hist_") + engine + (touching ? "_t" : "_k") + ".txt").c_str(), "w");
        for (const auto& h : r.history) std::fprintf(f, "%.17g %.17g %.17g\n", h.sliding, h.tangential_force, h.kinetic_energy);
        std::fclose(f);
      }
    }
}
