// The maximum of a Fig. 5.7 curve is read off the curve smoothed by a
// Savitzky-Golay filter of degree 3 on 11 points (§5.2): on a smooth curve it
// is the true maximum, a single noisy pixel does not move it, and invalid
// pixels (particles of the order of the cell) are not candidates.
#include <gtest/gtest.h>

#include <cmath>

#include "wearscale/wear/wear_curves.hpp"

using namespace wearscale::wear;

namespace {
// A map of 20 loads and one d*, counts from `count(load)`.
template <class F>
RoughWearMap map_of(F count, std::size_t loads = 20) {
  RoughWearMap m;
  m.spec.critical_diameters = {0.05};
  for (std::size_t l = 0; l < loads; ++l) {
    const double p = 0.01 * static_cast<double>(l + 1);
    m.spec.loads.push_back(p);
    WearMapPixel px;
    px.load = p;
    px.critical_diameter = 0.05;
    px.count_mean = count(p);
    m.pixels.push_back(px);
  }
  return m;
}
}  // namespace

TEST(WearCurves, TheMaximumOfASmoothCurveIsItsTrueMaximum) {
  // A cubic, left unchanged by the filter: n = 300 − 4e4 (p − 0.12)² + 1e5 (p − 0.12)³, maximum at p = 0.12.
  const auto m = map_of([](double p) { return 300.0 - 4e4 * std::pow(p - 0.12, 2) + 1e5 * std::pow(p - 0.12, 3); });
  const auto c = curve_maximum(m, 0);
  ASSERT_TRUE(c.found);
  EXPECT_EQ(c.window, 11);
  EXPECT_EQ(c.degree, 3);
  EXPECT_NEAR(c.load, 0.12, 1e-12);
  EXPECT_NEAR(c.count, 300.0, 1e-9);
}

TEST(WearCurves, ASingleNoisyPixelDoesNotMoveTheMaximum) {
  // A parabola peaking at p = 0.08 (265 particles) and one outlier at p = 0.16 of 280:
  // the raw maximum is the outlier, the smoothed one stays at the parabola's.
  const auto m = map_of([](double p) {
    const double n = 265.0 - 2e4 * (p - 0.08) * (p - 0.08);
    return std::fabs(p - 0.16) < 1e-9 ? 280.0 : n;
  });
  const auto c = curve_maximum(m, 0);
  ASSERT_TRUE(c.found);
  EXPECT_NEAR(c.load, 0.08, 0.0101) << "within one load step";
  EXPECT_NEAR(c.count, 265.0, 0.05 * 265.0);
}

TEST(WearCurves, InvalidPixelsAreNotCandidatesAndShortMapsUseASmallerWindow) {
  auto m = map_of([](double p) { return 1000.0 * p; }, 7);  // rising: the maximum is at the last load
  m.pixels[5].valid = m.pixels[6].valid = false;          // particles too large there
  const auto c = curve_maximum(m, 0);
  EXPECT_EQ(c.window, 7);
  EXPECT_EQ(c.degree, 3);
  ASSERT_TRUE(c.found);
  EXPECT_EQ(c.index, 4u);
  EXPECT_NEAR(c.count, 50.0, 1e-9);  // a line is unchanged by the filter
  for (auto& p : m.pixels) p.valid = false;
  EXPECT_FALSE(curve_maximum(m, 0).found);
}
