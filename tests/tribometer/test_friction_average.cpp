// Averages of μ over sliding distance (friction_average.hpp): every average is
// a difference of the integral ∫μ ds, so unevenly spaced samples (an adaptive
// run) weigh by the distance they cover, not by their number.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "wearscale/core/errors.hpp"
#include "wearscale/tribometer/friction_average.hpp"

using namespace wearscale;
using namespace wearscale::tribometer;

namespace {
// μ(s) = a + b sin(2π s / P), sampled where `at` says, with its exact integral.
FrictionAverage sampled(const std::vector<double>& at, double a, double b, double period) {
  std::vector<double> integral;
  for (double s : at)
    integral.push_back(a * s + b * period / (2.0 * std::numbers::pi) * (1.0 - std::cos(2.0 * std::numbers::pi * s / period)));
  return FrictionAverage(at, integral);
}
}  // namespace

TEST(FrictionAverage, MeansWeighByDistanceNotBySampleCount) {
  // μ = 0.8 over [0, 0.1) then 0.2 over [0.1, 1]: 100 samples in the first
  // tenth, 10 in the rest. Per distance the mean is 0.26; per sample it would be 0.75.
  std::vector<double> s, integral;
  for (int k = 0; k < 100; ++k) s.push_back(0.001 * k);
  for (int k = 0; k <= 9; ++k) s.push_back(0.1 + 0.1 * k);
  for (double x : s) integral.push_back(x < 0.1 ? 0.8 * x : 0.08 + 0.2 * (x - 0.1));
  const FrictionAverage average(s, integral);
  EXPECT_NEAR(average.mean(0.0, 1.0), 0.26, 1e-12);
  EXPECT_NEAR(average.mean(0.5, 1.0), 0.2, 1e-12);
  EXPECT_NEAR(average.mean(0.05, 0.15), 0.5, 1e-12);  // half on each side of the change
}

TEST(FrictionAverage, AMovingAverageOverOnePeriodRemovesTheOscillationOfARotatingTilt) {
  // Fig. 9.23: the window is the tilt's period. Samples at irregular spacing.
  std::vector<double> at;
  for (double s = 0.0; s <= 0.5; s += 0.0007 + 0.0006 * std::sin(37.0 * s)) at.push_back(s);
  const double period = 0.05;
  const auto average = sampled(at, 0.3, 0.1, period);
  const auto smooth = average.centred_moving_average(period);
  for (std::size_t k = 0; k < at.size(); ++k) {
    if (at[k] > period && at[k] < at.back() - period) {
      ASSERT_NEAR(smooth[k], 0.3, 2e-4) << at[k];
    }
  }
  // At the ends the window shrinks to the sampled range: the mean of what is there.
  EXPECT_NEAR(smooth.front(), average.mean(0.0, 0.5 * period), 1e-12);
}

TEST(FrictionAverage, TheFinalWindowIsTheLastWholeTiltPeriodElseTheLastFivePercent) {
  const auto tilt = final_window(0.0, 0.5, 0.05);
  EXPECT_DOUBLE_EQ(tilt.from, 0.45);
  EXPECT_DOUBLE_EQ(tilt.to, 0.5);
  // Its mean does not depend on the phase the run ends at (half a period would).
  for (double end : {0.5, 0.49, 0.48}) {
    std::vector<double> at;
    for (int k = 0; k <= 2000; ++k) at.push_back(end * k / 2000.0);
    const auto average = sampled(at, 0.3, 0.1, 0.05);
    const auto w = final_window(0.0, end, 0.05);
    EXPECT_NEAR(average.mean(w.from, w.to), 0.3, 1e-5) << end;
    EXPECT_GT(std::abs(average.mean(end - 0.025, end) - 0.3), 0.01) << "half a period depends on the phase";
  }
  const auto planar = final_window(0.0, 0.5, 0.0);
  EXPECT_DOUBLE_EQ(planar.from, 0.475);
  const auto short_run = final_window(0.0, 0.03, 0.05);
  EXPECT_DOUBLE_EQ(short_run.from, 0.0);
  EXPECT_NE(short_run.description.find("whole run"), std::string::npos);
  EXPECT_DOUBLE_EQ(initial_window(0.0, 0.5, 0.05).to, 0.05);
}

TEST(FrictionAverage, SamplesThatGoBackwardsAreRefused) {
  EXPECT_THROW(FrictionAverage({0.0, 0.2, 0.1}, {0.0, 0.1, 0.2}), InputError);
  EXPECT_THROW(FrictionAverage({0.0, 0.1}, {0.0}), InputError);
}
