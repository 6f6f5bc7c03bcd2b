// HCP patch tests of §6.2.1 (Table 6.4 targets, d0 = 0.6 d_c): the
// parameters (6.49)-(6.52) give the target E and ν within the thesis' 12 %
// (Figs. 6.8, 6.9). Reduced sample L = 15 d0 (thesis: 25 d0); loaded in the
// close-packed planes (along the c-axis ν comes out 20 % low at ν = 0.25).
#include <gtest/gtest.h>

#include "input_error_of.hpp"
#include "wearscale/dem/patch_test.hpp"

using namespace wearscale::dem;

namespace {
PatchTestSpec table_6_4(double poisson) {
  PatchTestSpec s;
  s.material = patch_test_targets();
  s.material.poisson = poisson;
  s.d0 = 90.0;  // 0.6 d_c, the smallest size of §6.2.1
  s.length = 15.0;
  s.strengths = false;
  return s;
}
}  // namespace

class HcpPatchTest : public ::testing::TestWithParam<double> {};

TEST_P(HcpPatchTest, YoungsModulusAndPoissonsRatioMatchTheTargetsWithinTwelvePercent) {
  const double nu = GetParam();
  const auto r = run_patch_test(table_6_4(nu));
  EXPECT_TRUE(r.elastic_converged);
  EXPECT_NEAR(r.young, 1.0, 0.12);  // measured 1.026 / 1.040 / 1.034
  if (nu == 0.0)
    EXPECT_NEAR(r.poisson, 0.0, 0.01);  // measured 0.0009
  else
    EXPECT_NEAR(r.poisson, nu, 0.12 * nu);  // measured 0.0955 / 0.2492
  EXPECT_DOUBLE_EQ(r.d_min, 30.0);
  EXPECT_DOUBLE_EQ(r.d_c, 150.0);
}

INSTANTIATE_TEST_SUITE_P(TargetPoisson, HcpPatchTest, ::testing::Values(0.0, 0.1, 0.25));

TEST(PatchTest, RefusesPoissonAboveOneQuarterAndLoadsBeyondTheStrength) {
  EXPECT_NE(input_error_of([] { run_patch_test(table_6_4(0.3)); }).find("0.25"), std::string::npos);
  auto s = table_6_4(0.1);
  s.load = 0.5;  // above σ_m,N / E = 0.2
  EXPECT_NE(input_error_of([&] { run_patch_test(s); }).find("load"), std::string::npos);
}
