// The main job at thesis size (label `long`; reduced versions in
// tests/tribometer/test_pin_on_disc.cpp and test_nonplanarity.cpp): n = 128,
// L = 2 mm, R = 3 mm, 1 N, 8 mm/s, dt = 0.02 s, 0.5 m.
//   ctest --test-dir build -L long -R MainJob
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "../thesis_pin_on_disc.hpp"

using namespace wearscale;
using namespace wearscale::tribometer;
using wearscale::tribometer::test_support::converged_crossing;

namespace {
PinOnDiscSetup thesis(double layer) { return test_support::thesis_setup(layer); }
using test_support::Outcome;
Outcome run(const PinOnDiscSetup& setup, bool adaptive = false) { return test_support::run_outcome(setup, adaptive); }

void expect_within(double got, double want, double rtol, const char* what, double h) {
  EXPECT_NEAR(got, want, rtol * std::abs(want)) << what << " at h_layer = " << h;
}
}  // namespace

// The main job: every run of cases/oxide_thickness_sweep.toml with the
// adaptive integrator (the default) at its default tolerances, against the
// explicit stepping converged in its step: a quarter of the thesis step
// (0.04 mm) for μ and the wear, 1/32 of it (5 µm) for the distance at which
// the substrate is reached (the explicit crossing is the first step boundary
// past it). Every figure within 0.1 %.
TEST(MainJob, TheAdaptiveSweepMatchesTheConvergedExplicitOneWithinATenthOfAPercent) {
  long adaptive_solves = 0, adaptive_iterations = 0;
  for (double h : {0.0, 0.5e-6, 1e-6, 2e-6, 3e-6, std::numeric_limits<double>::infinity()}) {
    const auto setup = thesis(h);
    auto converged = setup;
    converged.time_step /= 4.0;
    const auto e = run(converged), a = run(setup, true);
    expect_within(a.mu_mean, e.mu_mean, 1e-3, "mu_mean", h);
    expect_within(a.mu_final, e.mu_final, 1e-3, "mu_final", h);
    expect_within(a.pin, e.pin, 1e-3, "pin wear", h);
    expect_within(a.disc, e.disc, 1e-3, "disc wear", h);
    if (h > 0.0 && std::isfinite(h)) expect_within(a.reached, converged_crossing(setup, 32.0), 1e-3, "substrate reached", h);
    adaptive_solves += a.solves;
    adaptive_iterations += a.iterations;
  }
  RecordProperty("adaptive_solves", std::to_string(adaptive_solves));
  RecordProperty("adaptive_iterations", std::to_string(adaptive_iterations));
}

// The adaptive integrator on a tilted disc under the physical reading (its
// default there): 2 µm of oxide, slope 0.02 turning once per 0.05 m, against
// the explicit stepping at a quarter of the thesis step, every figure within 0.1 %.
TEST(MainJob, OnATiltedDiscTheAdaptiveIntegratorMatchesTheConvergedExplicitOne) {
  auto setup = thesis(2e-6);
  setup.nonplanar_slope = 0.02;
  auto converged = setup;
  converged.time_step /= 4.0;
  const auto e = run(converged), a = run(setup, true);
  expect_within(a.mu_mean, e.mu_mean, 1e-3, "mu_mean", 2e-6);
  expect_within(a.mu_final, e.mu_final, 1e-3, "mu_final", 2e-6);
  expect_within(a.pin, e.pin, 1e-3, "pin wear", 2e-6);
  expect_within(a.disc, e.disc, 1e-3, "disc wear", 2e-6);
  expect_within(a.reached, converged_crossing(setup, 32.0), 1e-3, "substrate reached", 2e-6);
  RecordProperty("adaptive_solves", std::to_string(a.solves));
}

// Deliver 3, layer_test = "tilted": the trends of Figs. 9.23-9.24.
TEST(MainJob, TheTiltedReadingReproducesTheTrendsOfFigs923And924) {
  auto planar = thesis(2e-6);
  planar.layer_test = LayerTest::Tilted;
  auto tilted = planar;
  tilted.nonplanar_slope = 0.02;
  const auto p = run(planar), t = run(tilted);
  EXPECT_GE(t.mu_final / p.mu_final, 1.5);
  EXPECT_LT(t.mu_first, 0.6);
  EXPECT_NEAR(t.pin + t.disc, p.pin + p.disc, 0.1 * (p.pin + p.disc));
  double previous = 0.0;
  for (double h : {0.5e-6, 1e-6, 2e-6, 3e-6}) {
    auto s = tilted;
    s.layer_thickness = h;
    const double mu = h == 2e-6 ? t.mu_final : run(s).mu_final;
    EXPECT_GT(mu, previous) << "h_layer = " << h;
    previous = mu;
  }
}

// Deliver 3, layer_test = "disc" (physical): the measured characterisation,
// as a regression. Fig. 9.22's two grooves are not reproduced.
TEST(MainJob, ThePhysicalReadingKeepsFinalFrictionOneGrooveAndTheWear) {
  auto planar = thesis(2e-6);
  auto tilted = planar;
  tilted.nonplanar_slope = 0.02;
  const auto p = run(planar), t = run(tilted);
  EXPECT_NEAR(t.mu_final / p.mu_final, 1.0, 0.1);
  EXPECT_EQ(t.grooves, 1);
  EXPECT_LT(t.several_grooves, 0.01 * tilted.distance);  // a second groove at most for a moment (a chattering step)
  EXPECT_NEAR(t.pin + t.disc, p.pin + p.disc, 0.05 * (p.pin + p.disc));
}

// Deliver 4: a resolved track on a planar disc without a layer slides at μ0
// and wears as the averaged one; the two differ only in where the wear goes.
TEST(MainJob, AResolvedTrackWithoutLayerSlidesAtMu0AndWearsAsTheAveragedOne) {
  auto averaged = thesis(0.0);
  auto resolved = averaged;
  resolved.track = Track::Resolved;
  const auto a = run(averaged), r = run(resolved);
  EXPECT_NEAR(r.mu_mean, averaged.on_substrate.mu0, 1e-9);
  EXPECT_NEAR(r.mu_final, averaged.on_substrate.mu0, 1e-9);
  EXPECT_NEAR(r.pin + r.disc, a.pin + a.disc, 0.01 * (a.pin + a.disc));
}
