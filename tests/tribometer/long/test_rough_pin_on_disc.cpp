// A rough pin on the main job's size (n = 64, 0.5 m, 1 µm of oxide, averaged
// track): the adaptive integrator against the explicit stepping at a quarter
// of the thesis step (measured: μ_mean, μ_final, both worn volumes within
// 0.02 %, the substrate 41.03 mm against 41.04 mm; 219 solves against 12 501).
// Long: 12 501 contact solves at n = 64.
#include <gtest/gtest.h>

#include "../thesis_pin_on_disc.hpp"
#include "wearscale/bem/roughness.hpp"
#include "wearscale/bem/spectral_modes.hpp"
#include "wearscale/bem/surface_generator.hpp"

using namespace wearscale;
using namespace wearscale::tribometer;

TEST(RoughPinOnDiscLong, OnARoughPinTheAdaptiveIntegratorMatchesTheConvergedExplicitStepping) {
  PinOnDiscSetup setup = test_support::thesis_setup(1e-6);
  setup.grid = 64;
  // pin_surface = {hurst = 0.8, k_l = 4, k_s = 16, sa = "0.5 um", seed = 5}
  bem::RoughSurfaceSpec spec;
  spec.grid = Grid2D::square(64, setup.size);
  spec.hurst = 0.8;
  spec.k_l = spec.k_r = 4.0;
  spec.k_s = 16.0;
  spec.seed = 5;
  const RealField h = bem::generate_surface(spec, bem::RoughnessMeasure::Sa, 0.5e-6);
  const double mean = bem::mean_height(h);
  setup.pin_roughness.assign(h.begin(), h.end());
  for (double& v : setup.pin_roughness) v -= mean;
  auto fine = setup;
  fine.time_step = setup.time_step / 4.0;
  const auto adaptive = test_support::run_outcome(setup, true), explicit_ = test_support::run_outcome(fine, false);
  test_support::expect_same_friction_and_wear(adaptive, explicit_, 1e-3);
  // The explicit crossing is the first step boundary past it: one step (0.04 mm) is its resolution.
  EXPECT_NEAR(adaptive.reached, explicit_.reached, setup.velocity * fine.time_step);
  EXPECT_LT(adaptive.solves, explicit_.solves / 10);
}
