// HCP patch test at the thesis size (L = 25 d0) with the strength tests: for
// a target ν = 0 the measured tensile strength matches the target (§6.2.1,
// Fig. 6.10); E and ν as in the reduced test. Long: about two minutes.
#include <gtest/gtest.h>

#include "wearscale/dem/patch_test.hpp"

using namespace wearscale::dem;

TEST(HcpPatchTestLong, TensileStrengthMatchesTheTargetForZeroPoisson) {
  PatchTestSpec s;
  s.material = patch_test_targets();
  s.material.poisson = 0.0;
  s.d0 = 90.0;
  s.length = 25.0;
  const auto r = run_patch_test(s);
  EXPECT_NEAR(r.young, 1.0, 0.05);
  ASSERT_TRUE(r.tensile_strength.has_value());
  EXPECT_NEAR(*r.tensile_strength, 0.2, 0.02);  // measured 0.212
  // The thesis finds the shear strength below target for d0 < d_c (Fig. 6.11);
  // ours is above it at ν = 0 (0.126 for 0.1; below it at ν = 0.15: 0.093):
  // reported, not asserted. Measured once: E = 1.015, ν = 0.001,
  // σ_m,N = 0.212 (`wearscale dem patch-test --nu 0 --d0 90 --length 25`).
  EXPECT_GT(*r.shear_strength, 0.0);
}
