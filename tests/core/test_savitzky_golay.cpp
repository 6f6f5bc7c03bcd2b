// Savitzky-Golay smoothing (degree 3 on 11 points reads the maximum of the
// thesis wear curves, §5.2): it leaves cubics unchanged, its interior weights
// are the classic convolution coefficients, and it removes most of the noise.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "wearscale/core/savitzky_golay.hpp"

using namespace wearscale;

namespace {
std::vector<double> grid(std::size_t n, double dx = 0.5) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = 1.0 + dx * static_cast<double>(i);
  return x;
}
}  // namespace

TEST(SavitzkyGolay, LeavesACubicUnchangedEverywhereIncludingTheEnds) {
  const auto x = grid(20);
  std::vector<double> y;
  for (double v : x) y.push_back(2.0 - 3.0 * v + 0.5 * v * v - 0.07 * v * v * v);
  const auto s = savitzky_golay(x, y);
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(s[i], y[i], 1e-11) << "point " << i;
}

// Smoothing a unit impulse gives the filter's weights: for 11 points and a
// cubic (same as a quadratic), (−36, 9, 44, 69, 84, 89, 84, 69, 44, 9, −36)/429.
TEST(SavitzkyGolay, InteriorWeightsAreTheClassicCoefficients) {
  const auto x = grid(31);
  std::vector<double> impulse(31, 0.0);
  impulse[15] = 1.0;
  const auto s = savitzky_golay(x, impulse);
  const double c[] = {-36, 9, 44, 69, 84, 89, 84, 69, 44, 9, -36};
  for (int k = -5; k <= 5; ++k) EXPECT_NEAR(s[static_cast<std::size_t>(15 + k)], c[k + 5] / 429.0, 1e-13) << k;
  EXPECT_NEAR(s[9], 0.0, 1e-13);  // outside the window
}

// White noise of variance σ² keeps Σ c_k² σ² = 89/429 σ² ≈ 0.207 σ² in the
// interior; over 20 000 points the sample variance is within 5 % of it.
TEST(SavitzkyGolay, ReducesWhiteNoiseVarianceToTheSumOfSquaredWeights) {
  const std::size_t n = 20000;
  const auto x = grid(n);
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> y(n);
  for (auto& v : y) v = noise(rng);
  const auto s = savitzky_golay(x, y);
  double var = 0.0;
  for (std::size_t i = 5; i + 5 < n; ++i) var += s[i] * s[i] / static_cast<double>(n - 10);
  EXPECT_NEAR(var, 89.0 / 429.0, 0.05 * 89.0 / 429.0);
}

TEST(SavitzkyGolay, RefusesWindowsItCannotFit) {
  const auto x = grid(10);
  const std::vector<double> y(10, 1.0);
  EXPECT_THROW(savitzky_golay(x, y), std::invalid_argument);  // 10 points < 11
  EXPECT_THROW(savitzky_golay(x, y, 4, 1), std::invalid_argument);  // even window
  EXPECT_THROW(savitzky_golay(x, y, 5, 5), std::invalid_argument);  // degree ≥ window
  auto reversed = x;
  std::swap(reversed[2], reversed[3]);
  EXPECT_THROW(savitzky_golay(reversed, y, 5, 2), std::invalid_argument);
}
