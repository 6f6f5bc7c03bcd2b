// Roughness amplitudes of §1.1.2 on surfaces whose values are known in closed
// form: Sa (1.4), h_RMS (1.5) and h'_RMS (1.6) of sines, and rescaling to a target.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "wearscale/bem/roughness.hpp"
#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/core/errors.hpp"

using namespace wearscale;
using namespace wearscale::bem;
using ::testing::HasSubstr;

namespace {
constexpr double pi = std::numbers::pi;

/// h = amplitude·sin(2π(kx·x/Lx + ky·y/Ly)) + offset
RealField sine(const Grid2D& g, double amplitude, double kx, double ky, double offset = 0.0) {
  RealField h(g);
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j)
      h(i, j) = offset + amplitude * std::sin(2.0 * pi * (kx * g.x(i) / g.lx + ky * g.y(j) / g.ly));
  return h;
}
}  // namespace

TEST(Roughness, HRmsOfASineIsAmplitudeOverRoot2) {
  // Σ sin² over whole periods of P > 2 samples is exactly P/2.
  const RealField h = sine(Grid2D(256, 32, 1e-3, 1e-4), 2e-6, 4.0, 0.0);
  EXPECT_NEAR(h_rms(h), 2e-6 / std::sqrt(2.0), 1e-14 * 2e-6);
}

TEST(Roughness, SaOfASampledSineIsTwoAOverPCotPiOverP) {
  // P = 64 samples per period: ⟨|sin|⟩ = (2/P)·Σ_{m<P/2} sin(2πm/P) = (2/P)·cot(π/P),
  // which tends to 2/π (the continuous value) as P grows.
  const double a = 1.5e-6, p = 64.0;
  const RealField h = sine(Grid2D(256, 8, 1.0, 1.0), a, 4.0, 0.0);
  EXPECT_NEAR(sa(h), a * 2.0 / p / std::tan(pi / p), 1e-14 * a);
  EXPECT_NEAR(sa(h), a * 2.0 / pi, 1e-3 * a);
}

TEST(Roughness, SaAndHRmsAreTakenAboutTheMean) {
  const Grid2D g = Grid2D::square(128, 1.0);
  const RealField h = sine(g, 1.0, 2.0, 3.0), lifted = sine(g, 1.0, 2.0, 3.0, 7.0);
  EXPECT_NEAR(sa(lifted), sa(h), 1e-12);
  EXPECT_NEAR(h_rms(lifted), h_rms(h), 1e-12);
  EXPECT_NEAR(mean_height(lifted), 7.0, 1e-12);
}

TEST(Roughness, SpectralSlopeOfASineIsAmplitudeTimesQOverRoot2) {
  // ∇h = A q cos(...) exactly for a band-limited periodic sine: h'_RMS = A·|q|/√2.
  const Grid2D g(128, 64, 2e-3, 1e-3);
  const double a = 1e-6;
  for (const auto& [kx, ky] : {std::pair{5.0, 0.0}, std::pair{0.0, 3.0}, std::pair{7.0, -4.0}}) {
    const double q = 2.0 * pi * std::hypot(kx / g.lx, ky / g.ly);
    EXPECT_NEAR(h_prime_rms(sine(g, a, kx, ky)) / (a * q / std::sqrt(2.0)), 1.0, 1e-12) << kx << "," << ky;
  }
}

TEST(Roughness, FiniteDifferenceSlopeOfASineFollowsItsDiscreteFormula) {
  // h = A sin(qx), forward differences 2A sin(θ) cos(q(x_i + dx/2))/dx with θ = q dx/2,
  // averaged over the n−1 pairs (no wrap): ⟨(∂h)²⟩ = (2A sinθ/dx)²·(n/2 − cos²θ)/(n−1).
  const std::size_t n = 256;
  const Grid2D g(n, 16, 1e-3, 1e-4);
  const double a = 1e-6, k = 4.0, q = 2.0 * pi * k / g.lx, theta = 0.5 * q * g.dx();
  const double nn = static_cast<double>(n);
  const double expected =
      2.0 * a * std::sin(theta) / g.dx() * std::sqrt((nn / 2.0 - std::cos(theta) * std::cos(theta)) / (nn - 1.0));
  const RealField h = sine(g, a, k, 0.0);
  EXPECT_NEAR(h_prime_rms_finite_difference(h) / expected, 1.0, 1e-12);
  // and it agrees with the spectral value to O(θ²) + O(1/n): within 0.5 %.
  EXPECT_NEAR(h_prime_rms_finite_difference(h) / h_prime_rms(h), 1.0, 5e-3);
}

TEST(Roughness, RescaleHitsEachMeasureToRoundOff) {
  const RealField base = generate_surface({Grid2D::square(128, 1e-4), 0.5, 2.0, 2.0, 32.0, 11});
  for (const auto& [measure, target] : {std::pair{RoughnessMeasure::HPrimeRms, 1.5},
                                        std::pair{RoughnessMeasure::HRms, 3e-8},
                                        std::pair{RoughnessMeasure::Sa, 1e-6}}) {
    RealField h = base;
    rescale(h, measure, target);
    EXPECT_NEAR(roughness(h, measure) / target, 1.0, 1e-12) << name(measure);
  }
}

TEST(Roughness, RescaleRefusesAFlatSurfaceAndNonPositiveTargets) {
  RealField flat = plane(Grid2D::square(16, 1.0), 3.0);
  try {
    rescale(flat, RoughnessMeasure::HRms, 1.0);
    FAIL() << "a flat surface was rescaled";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("flat"));
  }
  RealField h = sine(Grid2D::square(16, 1.0), 1.0, 1.0, 0.0);
  try {
    rescale(h, RoughnessMeasure::HPrimeRms, -1.0);
    FAIL() << "a negative target was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("h_prime_rms = -1"));
    EXPECT_THAT(e.what(), HasSubstr("> 0"));
  }
}
