// The main job at thesis size (label `long`; reduced versions in
// tests/tribometer/test_pin_on_disc.cpp and test_nonplanarity.cpp): n = 128,
// L = 2 mm, R = 3 mm, 1 N, 8 mm/s, dt = 0.02 s, 0.5 m.
//   ctest --test-dir build -L long -R MainJob
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "wearscale/tribometer/adaptive_wear.hpp"
#include "wearscale/tribometer/friction_average.hpp"
#include "wearscale/tribometer/pin_on_disc.hpp"
#include "../thesis_pin_on_disc.hpp"

using namespace wearscale;
using namespace wearscale::tribometer;
using wearscale::tribometer::test_support::converged_crossing;

namespace {
PinOnDiscSetup thesis(double layer) { return test_support::thesis_setup(layer); }

struct Outcome {
  double mu_mean = 0.0, mu_first = 0.0, mu_final = 0.0, pin = 0.0, disc = 0.0;
  double reached = std::numeric_limits<double>::quiet_NaN();
  double several_grooves = 0.0;  // sliding distance over which two or more grooves were open
  int grooves = 0, grooves_max = 0, solves = 0;
};

Outcome run(const PinOnDiscSetup& setup, bool adaptive = false) {
  PinOnDisc model(setup);
  std::vector<double> s, integral;
  Outcome out;
  auto observe = [&](const PinOnDiscSample& x) {
    if (!s.empty() && out.grooves >= 2) out.several_grooves += x.distance - s.back();
    s.push_back(x.distance);
    integral.push_back(x.friction_integral);
    if (x.substrate_contact > 0.0 && std::isnan(out.reached)) out.reached = x.distance;
    out.grooves = x.grooves;
    out.grooves_max = std::max(out.grooves_max, x.grooves);
    out.pin = x.pin_wear;
    out.disc = x.disc_wear;
  };
  if (adaptive)
    run_adaptive(model, {}, observe);
  else
    model.run(observe);
  const FrictionAverage average(s, integral);
  const double period = setup.nonplanar_slope > 0.0 ? setup.nonplanar_period : 0.0;
  const auto last = final_window(s.front(), s.back(), period), first = initial_window(s.front(), s.back(), period);
  out.mu_mean = average.mean(s.front(), s.back());
  out.mu_final = average.mean(last.from, last.to);
  out.mu_first = average.mean(first.from, first.to);
  out.solves = model.contact_solves();
  return out;
}

void expect_within(double got, double want, double rtol, const char* what, double h) {
  EXPECT_NEAR(got, want, rtol * std::abs(want)) << what << " at h_layer = " << h;
}
}  // namespace

// Deliver 1: every run of cases/oxide_thickness_sweep.toml, adaptive at its
// default tolerances against the explicit thesis step. The explicit one
// reports the first step boundary on the substrate and its chattering
// contact moves that by a step from run to run: the adaptive crossing is
// compared with where the explicit stepping converges (a quarter step)
// within one thesis step. Not with the thesis step's own crossing: at 2 µm
// it was 101.28, 101.44 and 101.60 mm in three runs of the same case (two
// contact solvers, the CLI and this test), two steps apart, where the
// quarter step gives 101.32 mm and the adaptive one 101.33 mm.
TEST(MainJob, TheAdaptiveSweepMatchesTheExplicitOneWithinOnePercentAtAThirdOfTheSolves) {
  long explicit_solves = 0, adaptive_solves = 0;
  for (double h : {0.0, 0.5e-6, 1e-6, 2e-6, 3e-6, std::numeric_limits<double>::infinity()}) {
    const auto setup = thesis(h);
    const auto e = run(setup), a = run(setup, true);
    expect_within(a.mu_mean, e.mu_mean, 0.01, "mu_mean", h);
    expect_within(a.mu_final, e.mu_final, 0.01, "mu_final", h);
    expect_within(a.pin, e.pin, 0.01, "pin wear", h);
    expect_within(a.disc, e.disc, 0.01, "disc wear", h);
    if (h > 0.0 && std::isfinite(h)) {
      const double step = setup.velocity * setup.time_step;
      EXPECT_NEAR(a.reached, converged_crossing(setup), step) << "substrate reached, h = " << h;
    }
    EXPECT_LE(3 * a.solves, e.solves) << "h_layer = " << h;
    explicit_solves += e.solves;
    adaptive_solves += a.solves;
  }
  RecordProperty("explicit_solves", std::to_string(explicit_solves));
  RecordProperty("adaptive_solves", std::to_string(adaptive_solves));
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
