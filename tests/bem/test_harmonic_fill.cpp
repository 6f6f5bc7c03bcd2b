// Harmonic (Laplace) filling of missing points: exact for discrete harmonic
// fields, bounded by the measured values around a hole, and only where asked.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "wearscale/bem/harmonic_fill.hpp"

using namespace wearscale;
using namespace wearscale::bem;

namespace {
RealField field(const Grid2D& g, double (*f)(double, double)) {
  RealField h(g);
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) h(i, j) = f(g.x(i), g.y(j));
  return h;
}
}  // namespace

TEST(HarmonicFill, APlaneWithAHoleIsFilledExactly) {
  const Grid2D g(24, 16, 2.4e-4, 3.2e-4);  // dx ≠ dy
  auto plane = [](double x, double y) { return 1e-6 + 3e-3 * x - 2e-3 * y; };
  const RealField exact = field(g, plane);
  RealField h = exact;
  std::vector<std::uint8_t> missing(h.size(), 0);
  for (std::size_t i = 5; i < 14; ++i)
    for (std::size_t j = 3; j < 9; ++j) missing[g.index(i, j)] = 1, h(i, j) = std::nan("");
  EXPECT_EQ(harmonic_fill(h, missing), 9u * 6u);
  for (std::size_t k = 0; k < h.size(); ++k) EXPECT_NEAR(h[k], exact[k], 1e-12 * 1e-6) << k;
}

TEST(HarmonicFill, ADiscreteHarmonicFieldIsFilledExactlyOnSquareCells) {
  // x² − y² has a zero 5-point Laplacian on square cells.
  const Grid2D g(20, 20, 1.0, 1.0);
  const RealField exact = field(g, [](double x, double y) { return x * x - y * y; });
  RealField h = exact;
  std::vector<std::uint8_t> missing(h.size(), 0);
  for (std::size_t i = 2; i < 18; i += 3)
    for (std::size_t j = 1; j < 19; j += 2) missing[g.index(i, j)] = 1, h(i, j) = 0.0;
  harmonic_fill(h, missing);
  for (std::size_t k = 0; k < h.size(); ++k) EXPECT_NEAR(h[k], exact[k], 1e-12) << k;
}

TEST(HarmonicFill, AHoleAtTheEdgeStaysWithinTheMeasuredValuesAndMeasuredPointsAreKept) {
  // Maximum principle: a harmonic fill lies between the extremes of its boundary values.
  const Grid2D g(16, 12, 1.0, 1.0);
  RealField h = field(g, [](double x, double y) { return std::sin(0.7 * x) * std::cos(0.4 * y); });
  const RealField measured = h;
  std::vector<std::uint8_t> missing(h.size(), 0);
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t j = 0; j < 4; ++j) missing[g.index(i, j)] = 1;  // the corner
  double lo = 1e9, hi = -1e9;
  for (std::size_t k = 0; k < h.size(); ++k)
    if (missing[k] == 0) lo = std::min(lo, h[k]), hi = std::max(hi, h[k]);
  harmonic_fill(h, missing);
  for (std::size_t k = 0; k < h.size(); ++k) {
    if (missing[k] == 0) {
      EXPECT_EQ(h[k], measured[k]);
    }
    EXPECT_GE(h[k], lo - 1e-12);
    EXPECT_LE(h[k], hi + 1e-12);
  }
}

TEST(HarmonicFill, NothingMeasuredIsRefused) {
  RealField h(Grid2D(4, 4, 1.0, 1.0));
  const std::vector<std::uint8_t> all(h.size(), 1);
  EXPECT_THROW(harmonic_fill(h, all), std::invalid_argument);
  const std::vector<std::uint8_t> none(h.size(), 0);
  EXPECT_EQ(harmonic_fill(h, none), 0u);
}

TEST(HarmonicFill, ExtremeHeightsAndSpacingsCannotOverflow) {
  // Found by fuzzing: heights near the largest double on a grid of very unequal, tiny steps.
  const Grid2D g(6, 5, 6e-300, 5e-290);
  RealField h(g);
  for (std::size_t k = 0; k < h.size(); ++k) h[k] = (k % 2 ? 1.0 : -1.0) * 1.7e308;
  std::vector<std::uint8_t> missing(h.size(), 0);
  missing[g.index(2, 2)] = missing[g.index(3, 2)] = 1;
  harmonic_fill(h, missing);
  for (double v : h) {
    EXPECT_TRUE(std::isfinite(v));
    EXPECT_LE(std::abs(v), 1.7e308);
  }
}
