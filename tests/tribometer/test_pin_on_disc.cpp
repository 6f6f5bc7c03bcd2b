// The pin-on-disc wear model (§9.3.2) against the macroscale section of
// VERIFICATION.md, on the thesis setup (n = 128, L = 2 mm, R = 3 mm, 1 N,
// 8 mm/s, dt = 0.02 s) over shortened sliding distances (the full 0.5 m runs
// are the case files and the `long` tests).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "wearscale/core/errors.hpp"
#include "wearscale/io/shipped_data.hpp"
#include "wearscale/tribometer/adaptive_wear.hpp"
#include "wearscale/tribometer/friction_average.hpp"
#include "wearscale/tribometer/pin_on_disc.hpp"
#include "thesis_pin_on_disc.hpp"

using namespace wearscale;
using namespace wearscale::tribometer;

namespace {
PinOnDiscSetup thesis(double layer, double distance) {
  PinOnDiscSetup s = test_support::thesis_setup(layer);
  s.distance = distance;
  return s;
}

std::vector<PinOnDiscSample> run(const PinOnDiscSetup& s) {
  PinOnDisc model(s);
  std::vector<PinOnDiscSample> out;
  model.run([&](const PinOnDiscSample& x) { out.push_back(x); });
  return out;
}

FrictionAverage average(const std::vector<PinOnDiscSample>& x) {
  std::vector<double> s, integral;
  for (const auto& e : x) {
    s.push_back(e.distance);
    integral.push_back(e.friction_integral);
  }
  return FrictionAverage(s, integral);
}

// μ averaged over the sliding distance (the integral the integrator carries).
double mean_friction(const std::vector<PinOnDiscSample>& x) { return average(x).mean(x.front().distance, x.back().distance); }

// First distance at which the pin touches the substrate.
double transition(const std::vector<PinOnDiscSample>& x) {
  for (const auto& e : x)
    if (e.substrate_contact > 0.0) return e.distance;
  return std::numeric_limits<double>::infinity();
}

}  // namespace

TEST(PinOnDisc, BareSiliconSlidesAtMuSiThroughout) {
  for (const auto& e : run(thesis(0.0, 0.1))) ASSERT_NEAR(e.friction, 0.14, 0.005) << "s = " << e.distance;
}

TEST(PinOnDisc, BulkSilicaSlidesAtMuSiO2Throughout) {
  const auto x = run(thesis(std::numeric_limits<double>::infinity(), 0.1));
  for (const auto& e : x) ASSERT_NEAR(e.friction, 0.84, 0.005) << "s = " << e.distance;
  // Like on like: pin and disc wear alike (9.24)-(9.25).
  EXPECT_NEAR(x.back().pin_wear, x.back().disc_wear, 1e-6 * x.back().disc_wear);
}

TEST(PinOnDisc, OneMicronOfOxideWearsThroughNearThreeCentimetres) {
  const auto x = run(thesis(1e-6, 0.1));
  const double s_t = transition(x);
  EXPECT_GT(s_t, 0.02);  // thesis: μ ≈ 0.84 until about s = 0.03 m (Fig. 9.20)
  EXPECT_LT(s_t, 0.06);
  for (const auto& e : x) {
    if (e.distance < 0.9 * s_t) {
      ASSERT_NEAR(e.friction, 0.84, 0.005);
    }
  }
  EXPECT_LT(x.back().friction, 0.4);  // falling toward μ_Si
  EXPECT_GT(x.back().friction, 0.14);
}

TEST(PinOnDisc, PinWearSlowsAtTheTransitionWhileTotalWearRateStaysNearlyConstant) {
  const auto x = run(thesis(1e-6, 0.1));
  const double s_t = transition(x);
  auto at = [&](double s) {
    for (const auto& e : x)
      if (e.distance >= s) return e;
    return x.back();
  };
  const auto a = at(0.25 * s_t), b = at(0.75 * s_t), c = at(0.08), d = at(0.1);
  const double pin_before = (b.pin_wear - a.pin_wear) / (b.distance - a.distance);
  const double pin_after = (d.pin_wear - c.pin_wear) / (d.distance - c.distance);
  const double total_before = (b.pin_wear + b.disc_wear - a.pin_wear - a.disc_wear) / (b.distance - a.distance);
  const double total_after = (d.pin_wear + d.disc_wear - c.pin_wear - c.disc_wear) / (d.distance - c.distance);
  EXPECT_LT(pin_after, 0.5 * pin_before);
  // F/p_crit of the interfaces: 1/8.5 GPa⁻¹ on oxide, 1/10.6 GPa⁻¹ on Si: within 20 %.
  EXPECT_NEAR(total_after / total_before, 1.0, 0.2);
  EXPECT_NEAR(total_before, 1.0 / 8.5e9, 0.01 / 8.5e9);  // dV/ds = Σ p/p_crit ΔA = F/p_crit (9.21)
}

TEST(PinOnDisc, ThickerOxideDelaysTheTransitionRaisesMuAndSparesTheDisc) {
  const auto thin = run(thesis(0.5e-6, 0.1)), thick = run(thesis(1e-6, 0.1));
  EXPECT_LT(transition(thin), transition(thick));
  EXPECT_LT(mean_friction(thin), mean_friction(thick));
  EXPECT_GT(thin.back().disc_wear, thick.back().disc_wear);
}

// The adaptive integrator (the default) against the explicit stepping
// converged in its step, on a reduced sweep (n = 32, 0.1 m: bare Si, 0.5 and
// 1 µm of oxide, bulk SiO2): μ_mean, μ_final, both worn volumes and the
// distance at which the substrate is reached within 0.1 %. The explicit
// reference steps a quarter of the thesis step (0.04 mm; halving it again
// moves none of these by more than 0.01 %), and for the crossing 1/32 of it
// (5 µm, 0.03 % of the 0.5 µm run's 15.8 mm: the explicit crossing is the
// first step boundary past it). Stage solves and iterations are recorded.
class AdaptiveAgainstConvergedExplicit : public ::testing::TestWithParam<double> {};

TEST_P(AdaptiveAgainstConvergedExplicit, AgreesWithinATenthOfAPercentAtAThirdOfTheThesisStepsSolves) {
  using test_support::Outcome;
  auto setup = thesis(GetParam(), 0.1);
  setup.grid = 32;
  auto converged = setup;
  converged.time_step /= 4.0;
  const Outcome e = test_support::run_outcome(converged, false), a = test_support::run_outcome(setup, true);
  const double h = GetParam();
  test_support::expect_same_friction_and_wear(a, e, 1e-3);
  if (h > 0.0 && std::isfinite(h)) {
    const double crossing = test_support::converged_crossing(setup, 32.0);
    EXPECT_NEAR(a.reached, crossing, 1e-3 * crossing);
  } else {
    EXPECT_EQ(std::isnan(a.reached), h > 0.0);  // bare Si: the substrate from the start; bulk SiO2: never
  }
  PinOnDisc thesis_step(setup);
  EXPECT_LE(3 * a.solves, static_cast<int>(thesis_step.total_steps()) + 1);
  RecordProperty("adaptive_solves", a.solves);
  RecordProperty("adaptive_iterations_per_solve", std::to_string(static_cast<double>(a.iterations) / a.solves));
}

INSTANTIATE_TEST_SUITE_P(OxideThickness, AdaptiveAgainstConvergedExplicit,
                         ::testing::Values(0.0, 0.5e-6, 1e-6, std::numeric_limits<double>::infinity()),
                         [](const auto& p) {
                           return p.param == 0.0             ? std::string("bare_silicon")
                                  : !std::isfinite(p.param) ? std::string("bulk_silica")
                                  : p.param < 0.75e-6       ? std::string("half_micron")
                                                            : std::string("one_micron");
                         });

// The stage solves preconditioned by the stage's own (K(0) + A)⁻¹ against
// unpreconditioned ones: the same run (the stages are solved to the stage
// tolerance either way) in fewer BEM iterations, through the oxide transition.
TEST(PinOnDisc, TheStagePreconditionerGivesTheSameRunInFewerIterations) {
  auto setup = thesis(1e-6, 0.1);
  setup.grid = 32;
  auto plain = setup;
  plain.stage_preconditioner = false;
  const auto with = test_support::run_outcome(setup, true), without = test_support::run_outcome(plain, true);
  EXPECT_NEAR(with.mu_mean, without.mu_mean, 1e-4 * without.mu_mean);
  EXPECT_NEAR(with.pin, without.pin, 1e-4 * without.pin);
  EXPECT_NEAR(with.reached, without.reached, 1e-4 * without.reached);
  const double per_solve = static_cast<double>(with.iterations) / with.solves;
  const double per_solve_plain = static_cast<double>(without.iterations) / without.solves;
  EXPECT_LT(per_solve, 0.8 * per_solve_plain);
  RecordProperty("iterations_per_solve", std::to_string(per_solve));
  RecordProperty("iterations_per_solve_unpreconditioned", std::to_string(per_solve_plain));
}

TEST(PinOnDisc, AdaptiveStepsResolveARotatingTiltAndStayWithinACellOnAResolvedTrack) {
  auto setup = thesis(2e-6, 0.02);
  setup.grid = 32;
  setup.nonplanar_slope = 0.02;
  EXPECT_DOUBLE_EQ(adaptive_step_cap(setup, {}), 0.05 / 40);
  PinOnDisc model(setup);
  double previous = 0.0, widest = 0.0;
  run_adaptive(model, {}, [&](const PinOnDiscSample& x) {
    widest = std::max(widest, x.distance - previous);
    previous = x.distance;
  });
  EXPECT_LE(widest, 0.05 / 40 * (1 + 1e-9));
  // Resolved: the tilt turns once per revolution (6.28 mm / 40 = 0.157 mm),
  // and the step is at most one 62.5 µm cell.
  setup.track = Track::Resolved;
  setup.nonplanar_period = setup.path_length;
  EXPECT_DOUBLE_EQ(adaptive_step_cap(setup, {}), setup.size / 32);
}

TEST(PinOnDisc, BadParametersAreRefusedByName) {
  auto s = thesis(-1e-6, 0.1);
  try {
    PinOnDisc m(s);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("layer_thickness"));
  }
  s = thesis(1e-6, 0.1);
  s.on_layer = {};
  EXPECT_THROW(PinOnDisc{s}, InputError);
}
