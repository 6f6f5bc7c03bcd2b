// The drivers on both engines (reduced sizes): the LAMMPS engine measures
// what wearscale's own does. The patch test's sample comes to rest, so its
// E and ν agree closely. (The sliding cells, Fig. 7.2's peak p_T and the
// rough shear's mean μ, are compared at P = 1, 2, 3 in tests/mpi/mpi_dem_lammps.cpp.)
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
