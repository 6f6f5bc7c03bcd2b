// HCP patch tests of §6.2.1 (Table 6.4 targets, d0 = 0.6 d_c): the
// parameters (6.49)-(6.52) give the target E and ν within the thesis' 12 %
// (Figs. 6.8, 6.9). Reduced sample L = 15 d0 (thesis: 25 d0); loaded in the
// close-packed planes (along the c-axis ν comes out 20 % low at ν = 0.25).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "input_error_of.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/dem/cohesive_law.hpp"
#include "wearscale/dem/patch_test.hpp"
#include "wearscale/materials/material.hpp"

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

// §6.2.1: the lattice's elastic constants do not depend on d0 — as long as
// each particle bonds to its 12 nearest neighbours only. Second neighbours
// (√2 d0 apart) within δ_f = 30 attract in the softening branch of (6.3)
// and the lattice measured ν = 2.2 at d0 = 70: refused, naming the smallest
// d0 whose second neighbours stay beyond δ_f under the test's 1 % strain.
TEST(PatchTest, RefusesALatticeWhoseSecondNeighboursFallInsideTheCohesiveReach) {
  for (double d0 : {40.0, 70.0, 74.0}) {
    auto s = table_6_4(0.1);
    s.d0 = d0;
    const std::string why = input_error_of([&] { run_patch_test(s); });
    EXPECT_THAT(why, testing::HasSubstr("second neighbours")) << d0;
    EXPECT_THAT(why, testing::HasSubstr("Allowed: d0 ≥ 74.99")) << d0;
  }
  auto s = table_6_4(0.1);
  s.d0 = 74.99;
  const auto smallest = run_patch_test(s);
  const auto reference = run_patch_test(table_6_4(0.1));  // d0 = 90
  EXPECT_NEAR(smallest.young, reference.young, 1e-6 * reference.young);
  EXPECT_NEAR(smallest.poisson, reference.poisson, 1e-6 * reference.poisson);
  EXPECT_NEAR(smallest_hcp_spacing(s.material), 30.0 / (std::sqrt(2.0) - 1.0), 1e-9);
}

// A sample that does not come to rest under the load measures no elastic
// constants: 0.4 Δt_c heats the lattice (the wall stops, the particles keep
// vibrating; measured E = 0.71, ν = 0.25 against 1.04, 0.14 at 0.1 Δt_c),
// 0.3 Δt_c at ν = 0.1 never stops the wall (E = −1.6, ν = −10.9 after
// 40 000 steps). Both are numerical failures, not results.
TEST(PatchTest, ASampleThatDoesNotComeToRestIsANumericalFailure) {
  auto hot = table_6_4(0.15);
  hot.length = 8.0;
  hot.time_step = 0.4;
  EXPECT_THROW(
      {
        try {
          run_patch_test(hot);
        } catch (const wearscale::NumericalError& e) {
          EXPECT_THAT(e.what(), testing::HasSubstr("kinetic energy"));
          EXPECT_THAT(e.what(), testing::HasSubstr("0.4 Δt_c"));
          throw;
        }
      },
      wearscale::NumericalError);
  auto moving = table_6_4(0.1);
  moving.length = 8.0;
  moving.time_step = 0.3;
  moving.max_elastic_steps = 4000;
  EXPECT_THROW(
      {
        try {
          run_patch_test(moving);
        } catch (const wearscale::NumericalError& e) {
          EXPECT_THAT(e.what(), testing::HasSubstr("did not come to rest"));
          throw;
        }
      },
      wearscale::NumericalError);
}

// E ≤ 0 or ν outside (−1, 1/2) is no elastic solid: the constants the
// unstable run above measured (C11 = −1.79, C12 = −1.97) are refused.
TEST(PatchTest, ElasticConstantsOutsideWhatASolidAllowsAreANumericalFailure) {
  const auto good = isotropic_constants(1.0, 0.25, 0);  // ν = 0.2
  EXPECT_NEAR(good.poisson, 0.2, 1e-12);
  EXPECT_NEAR(good.young, 1.0 * 1.2 * 0.6 / 0.8, 1e-12);
  EXPECT_THROW(isotropic_constants(-1.79, -1.97, 40000), wearscale::NumericalError);  // ν = 0.52
  EXPECT_THROW(isotropic_constants(1.0, 1.2, 1), wearscale::NumericalError);          // ν = 0.55
  EXPECT_THROW(isotropic_constants(1.0, -1.0, 1), wearscale::NumericalError);         // 0/0
  EXPECT_THROW(isotropic_constants(-1.0, 0.1, 1), wearscale::NumericalError);         // E < 0
}

// The 2.4 nm deep cell of §7.1.1 (one HCP cell, two close-packed layers,
// each particle bonded to the other layer through two periodic images):
// the same E and ν as a sample three cells deep (within 3 %; the strain is
// uniform, so they agree to rounding: measured 2e-14).
TEST(PatchTest, AOneCellDeepSilicaLatticeHasTheElasticConstantsOfADeepOne) {
  PatchTestSpec s;
  s.material = cohesive_material(wearscale::materials::silica(), 0.5);
  s.d0 = 1.5e-9;
  s.length = 10.0;
  s.strengths = false;
  s.width = 1.6;  // round(1.6 / √(8/3)) = 1 cell: 2.45 nm
  const auto thin = run_patch_test(s);
  s.width = 4.9;  // 3 cells: 7.35 nm
  const auto deep = run_patch_test(s);
  EXPECT_NEAR(thin.young, deep.young, 1e-9 * deep.young);
  EXPECT_NEAR(thin.poisson, deep.poisson, 1e-9 * deep.poisson);
  EXPECT_LT(thin.particles, deep.particles / 2);
  EXPECT_NEAR(deep.young, 73e9, 0.12 * 73e9);  // and both near the target (§6.2.1)
}
