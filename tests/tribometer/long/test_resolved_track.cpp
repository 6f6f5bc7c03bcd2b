// The resolved wear track converged in its step (n = 32, 62.5 µm cells; 1 µm
// of oxide through the transition, 0.06 m): the adaptive integrator, whose
// steps are at most one cell, against the explicit stepping at a quarter of a
// cell a step (measured: μ_mean, both worn volumes and the substrate distance
// within 0.07 %; μ_final, over the last 5 %, 0.7 %). Long: 960-3 841 contact
// solves a run, three runs.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "../thesis_pin_on_disc.hpp"

using namespace wearscale;
using namespace wearscale::tribometer;

namespace {
std::string g(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", x);
  return b;
}
}  // namespace

TEST(ResolvedTrack, OnAnOxideTheAdaptiveIntegratorAgreesWithTheExplicitStepAtAQuarterCell) {
  PinOnDiscSetup setup = test_support::thesis_setup(1e-6);
  setup.grid = 32;
  setup.distance = 0.06;
  setup.track = Track::Resolved;
  auto fine = setup, cell = setup;
  fine.time_step = setup.size / 32 / 4 / setup.velocity;
  const auto quarter = test_support::run_outcome(fine, false), adaptive = test_support::run_outcome(setup, true);
  const auto one_cell = test_support::run_outcome(cell, false);  // the bounded thesis step: one cell
  for (const auto& [name, o] : {std::pair{"quarter", quarter}, std::pair{"adaptive", adaptive},
                                std::pair{"cell", one_cell}}) {
    RecordProperty(std::string("mu_mean_") + name, g(o.mu_mean));
    RecordProperty(std::string("mu_final_") + name, g(o.mu_final));
    RecordProperty(std::string("pin_") + name, g(o.pin));
    RecordProperty(std::string("disc_") + name, g(o.disc));
    RecordProperty(std::string("reached_") + name, g(o.reached));
    RecordProperty(std::string("solves_") + name, o.solves);
  }
  EXPECT_NEAR(adaptive.mu_mean, quarter.mu_mean, 2e-3 * quarter.mu_mean);
  EXPECT_NEAR(adaptive.pin, quarter.pin, 2e-3 * quarter.pin);
  EXPECT_NEAR(adaptive.disc, quarter.disc, 2e-3 * quarter.disc);
  EXPECT_NEAR(adaptive.reached, quarter.reached, 2e-3 * quarter.reached);
}
