// Topography analysis of §1.1.2 and §8.1.1: levelling, the radial Hann window,
// the PSD (1.9)/(8.5) and its radial average, and the log-log fit for H.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "wearscale/bem/roughness.hpp"
#include "wearscale/bem/spectral_modes.hpp"
#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/bem/topography.hpp"
#include "wearscale/core/errors.hpp"

using namespace wearscale;
using namespace wearscale::bem;
using ::testing::HasSubstr;

namespace {
constexpr double pi = std::numbers::pi;

RealField wave(const Grid2D& g, double amplitude, double k, bool cosine = false) {
  RealField h(g);
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) {
      const double phase = 2.0 * pi * k * g.x(i) / g.lx;
      h(i, j) = amplitude * (cosine ? std::cos(phase) : std::sin(phase));
    }
  return h;
}
}  // namespace

TEST(Topography, RemovePlaneRemovesATiltedPlaneExactly) {
  const Grid2D g(100, 60, 2e-3, 1e-3);
  RealField h = add(tilted_plane(g, 0.03, -0.02), plane(g, 1e-6));
  const PlaneFit p = remove_plane(h);
  EXPECT_NEAR(p.slope_x, 0.03, 1e-14);
  EXPECT_NEAR(p.slope_y, -0.02, 1e-14);
  EXPECT_NEAR(p.offset, 1e-6, 1e-17);
  for (const double v : h) ASSERT_NEAR(v, 0.0, 1e-17);  // heights were up to 6e-5 m
}

TEST(Topography, RemovePlaneLeavesARoughSurfaceUntiltedAndMeanFree) {
  const Grid2D g = Grid2D::square(64, 1.0);
  RealField h = add(generate_surface({g, 0.5, 2, 2, 16, 5}, RoughnessMeasure::HRms, 1.0), tilted_plane(g, 0.5, 0.2));
  remove_plane(h);
  const PlaneFit again = fit_plane(h);
  EXPECT_NEAR(again.slope_x, 0.0, 1e-13);
  EXPECT_NEAR(again.slope_y, 0.0, 1e-13);
  EXPECT_NEAR(mean_height(h), 0.0, 1e-13);
}

TEST(Topography, HannWindowIsOneAtTheCentreAndZeroFromHalfTheShorterSide) {
  const Grid2D g(65, 41, 2.0, 1.0);  // odd sizes: a grid point sits on the centre
  const RealField w = radial_hann_window(g);
  const double radius = 0.5, xc = g.x(32), yc = g.y(20);
  EXPECT_DOUBLE_EQ(w(32, 20), 1.0);
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) {
      const double r = std::hypot(g.x(i) - xc, g.y(j) - yc);
      const double expected = r < radius ? std::pow(std::cos(pi * r / (2.0 * radius)), 2) : 0.0;
      ASSERT_NEAR(w(i, j), expected, 1e-15) << i << "," << j;
      ASSERT_NEAR(w(i, j), w(g.nx - 1 - i, g.ny - 1 - j), 1e-15);  // symmetric about the centre
    }
}

TEST(Topography, HannWindowEnergyIsThreePiOver32MinusOneOver2Pi) {
  // ⟨w²⟩ over an L × L square of cos⁴(πr/L) inside r < L/2: (π/2)(3/16 − 1/π²) = 0.13537.
  const RealField w = radial_hann_window(Grid2D::square(256, 1.0));
  double energy = 0.0;
  for (const double v : w) energy += v * v;
  energy /= static_cast<double>(w.size());
  EXPECT_NEAR(energy, 3.0 * pi / 32.0 - 1.0 / (2.0 * pi), 1e-3);
}

TEST(TopographyPsd, PsdOfACosineIsLxLyAmplitudeSquaredOverFourAtItsWavenumber) {
  // ĥ(±k, 0) = N·a/2, so C = LxLy/N² · N²a²/4 = LxLy·a²/4 there and 0 elsewhere  (1.9)
  const Grid2D g(64, 32, 2e-3, 1e-3);
  const double a = 1e-6;
  const RealField c = psd_2d(wave(g, a, 5.0, true));
  const double line = g.area() * a * a / 4.0;
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.spectral_ny(); ++j) {
      const bool on_line = j == 0 && (i == 5 || i == g.nx - 5);
      ASSERT_NEAR(c(i, j), on_line ? line : 0.0, 1e-12 * line) << i << "," << j;
    }
}

TEST(TopographyPsd, PsdSumsToAreaTimesMeanSquareHeight) {
  // Parseval: Σ over the full spectrum of C = LxLy·⟨h²⟩.
  const Grid2D g(48, 40, 1e-3, 1e-3);
  const RealField h = generate_surface({g, 0.4, 1, 1, 20, 9}, RoughnessMeasure::HRms, 1e-6);
  const RealField c = psd_2d(h);
  double total = 0.0;
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.spectral_ny(); ++j) total += mode_multiplicity(g, j) * c(i, j);
  EXPECT_NEAR(total / (g.area() * 1e-12), 1.0, 1e-12);
}

TEST(TopographyPsd, RadialBinsHoldEveryModeOnceAndKeepTheTotalPower) {
  for (const Grid2D& g : {Grid2D::square(64, 1.0), Grid2D(33, 47, 1.0, 1.0), Grid2D(64, 32, 2.0, 1.0)}) {
    const RealField c = psd_2d(generate_surface({g, 0.8, 1, 1, std::floor(nyquist_wavenumber(g)), 2}));
    const RadialPsd r = radial_psd(c);
    EXPECT_EQ(std::accumulate(r.count.begin(), r.count.end(), std::size_t{1}), g.size()) << g.to_string();
    double binned = 0.0, total = 0.0;
    for (std::size_t b = 0; b < r.q.size(); ++b) binned += r.c[b] * static_cast<double>(r.count[b]);
    for (std::size_t i = 0; i < g.nx; ++i)
      for (std::size_t j = 0; j < g.spectral_ny(); ++j) total += mode_multiplicity(g, j) * c(i, j);
    EXPECT_NEAR(binned / total, 1.0, 1e-12) << g.to_string();
    for (std::size_t b = 1; b < r.q.size(); ++b) ASSERT_GT(r.q[b], r.q[b - 1]);
  }
}

TEST(TopographyPsd, HannWindowedPsdOfASinePeaksAtItsWavenumber) {
  // k = 10 (periodic) and k = 10.4 (not periodic, as measured data): the windowed
  // 2D PSD peaks on mode (±10, 0) (a real wave's PSD is even in k: which of the two
  // equal peaks rounds higher depends on the FFT plan) and the radial PSD in the bin
  // 10 ≤ |k| < 11.
  const Grid2D g = Grid2D::square(128, 1e-3);
  const RealField w = radial_hann_window(g);
  for (const double k : {10.0, 10.4}) {
    const RealField c = psd_2d(windowed(wave(g, 1e-6, k), w));
    const auto peak = static_cast<std::size_t>(std::max_element(c.begin(), c.end()) - c.begin());
    const std::size_t row = peak / c.cols();
    EXPECT_EQ(std::min(row, g.nx - row), 10u) << k;
    EXPECT_EQ(peak % c.cols(), 0u) << k;
    const RadialPsd r = radial_psd(c);
    const auto top = static_cast<std::size_t>(std::max_element(r.c.begin(), r.c.end()) - r.c.begin());
    EXPECT_GE(r.q[top], 10.0 * wavenumber_unit(g)) << k;
    EXPECT_LT(r.q[top], 11.0 * wavenumber_unit(g)) << k;
  }
}

TEST(TopographyPsd, WindowEnergyNormalisationPreservesThePsdLevel) {
  // Total power Σ C = LxLy⟨h²⟩ of a windowed sine stays LxLy·a²/2 within 1 %
  // (the window varies slowly compared with the sine).
  const Grid2D g = Grid2D::square(128, 1e-3);
  const double a = 1e-6;
  const RealField h = windowed(wave(g, a, 20.0), radial_hann_window(g));
  EXPECT_NEAR(h_rms(h) / (a / std::sqrt(2.0)), 1.0, 1e-2);
}

TEST(HurstFit, RecoversTheExponentOfAnExactPowerLaw) {
  RadialPsd r;
  for (int k = 1; k <= 50; ++k) {
    r.q.push_back(2.0 * pi * k);
    r.c.push_back(3e-20 * std::pow(2.0 * pi * k, -2.0 * (0.35 + 1.0)));
    r.count.push_back(static_cast<std::size_t>(6 * k));
  }
  const HurstFit fit = fit_hurst(r, 2.0 * pi * 5.0, 2.0 * pi * 40.0);
  EXPECT_NEAR(fit.hurst, 0.35, 1e-12);
  EXPECT_NEAR(fit.slope, -2.7, 1e-12);
  EXPECT_NEAR(fit.hurst_error, 0.0, 1e-10);
  EXPECT_EQ(fit.points, 36u);
  EXPECT_DOUBLE_EQ(fit.q_min, 2.0 * pi * 5.0);
  EXPECT_DOUBLE_EQ(fit.q_max, 2.0 * pi * 40.0);
}

TEST(HurstFit, ErrorIsHalfTheSlopeStandardError) {
  // ln q = 0, 1, 2 and ln C = 0, δ, 0 with equal weights: β = 0, residuals
  // (−δ/3, 2δ/3, −δ/3), s² = χ²/(n−2) = 2δ²/3, σ_β² = s²/Σ(x−x̄)² = δ²/3, so
  // H = −1 and σ_H = δ/(2√3).
  const double delta = 0.3;
  const RadialPsd r{{1.0, std::exp(1.0), std::exp(2.0)}, {1.0, std::exp(delta), 1.0}, {4, 4, 4}};
  const HurstFit fit = fit_hurst(r, 0.5, 10.0);
  EXPECT_NEAR(fit.slope, 0.0, 1e-14);
  EXPECT_NEAR(fit.hurst, -1.0, 1e-14);
  EXPECT_NEAR(fit.slope_error, delta / std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(fit.hurst_error, delta / (2.0 * std::sqrt(3.0)), 1e-14);
}

TEST(HurstFit, RefusesABandWithFewerThanThreeBins) {
  const RadialPsd r{{1.0, 2.0, 3.0, 4.0}, {1.0, 0.5, 0.3, 0.2}, {1, 1, 1, 1}};
  try {
    fit_hurst(r, 1.5, 3.5);
    FAIL() << "a two-bin band was fitted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("holds 2 PSD bin(s)"));
    EXPECT_THAT(e.what(), HasSubstr("at least 3"));
  }
  EXPECT_THROW(fit_hurst(r, 3.0, 2.0), InputError);
}
