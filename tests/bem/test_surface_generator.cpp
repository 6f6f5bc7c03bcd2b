// Rough surfaces generated from the PSD of Fig. 1.3 (thesis §1.1.2, VERIFICATION.md
// "Rough surfaces"): the PSD is the target inside [k_l, k_s] and zero outside,
// a fit on it recovers H within ±0.05, a seed fixes the surface, bad parameters
// are refused by name; and the simple surfaces (sphere, planes) are exact.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <string>

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

RoughSurfaceSpec spec_on(Grid2D grid, double hurst, double k_l, double k_r, double k_s, std::uint64_t seed = 1) {
  return RoughSurfaceSpec{grid, hurst, k_l, k_r, k_s, seed};
}

std::string rejection(const RoughSurfaceSpec& s) {
  try {
    generate_surface(s);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}
}  // namespace

TEST(SurfaceGenerator, PsdEqualsTheTargetInsideTheBandAndIsZeroOutside) {
  // Square, rectangular-grid and odd-sized grids on a square domain: every mode,
  // including the self-conjugate ones on the axes and the Nyquist row (k_s = n/2),
  // carries exactly C = target (Hermitian consistency loses nothing in c2r).
  for (const Grid2D& g : {Grid2D::square(128, 1e-3), Grid2D(64, 96, 1e-3, 1e-3), Grid2D(63, 65, 1e-3, 1e-3)}) {
    const auto s = spec_on(g, 0.6, 3.0, 6.0, std::floor(nyquist_wavenumber(g)));
    const RealField c = psd_2d(generate_surface(s));
    const double c_max = *std::max_element(c.begin(), c.end());
    std::size_t in_band = 0;
    for (std::size_t i = 0; i < g.nx; ++i)
      for (std::size_t j = 0; j < g.spectral_ny(); ++j) {
        const double target = target_psd(s, radial_wavenumber(g, i, j));
        if (target == 0.0) {
          ASSERT_LE(c(i, j), 1e-24 * c_max) << g.to_string() << " mode " << i << "," << j;  // round-off only
        } else {
          ++in_band;
          ASSERT_NEAR(c(i, j) / target, 1.0, 1e-9) << g.to_string() << " mode " << i << "," << j;
        }
      }
    EXPECT_GT(in_band, 100u) << g.to_string();
  }
}

TEST(SurfaceGenerator, PsdHasAPlateauBelowRollOffAndSlopeMinus2HPlus1Above) {
  const auto s = spec_on(Grid2D::square(64, 1.0), 0.8, 2.0, 5.0, 20.0);
  EXPECT_EQ(target_psd(s, 1.999), 0.0);
  EXPECT_EQ(target_psd(s, 2.0), 1.0);
  EXPECT_EQ(target_psd(s, 4.9), 1.0);
  EXPECT_DOUBLE_EQ(target_psd(s, 10.0), std::pow(2.0, -3.6));  // (q/q_r)^β, β = −2(0.8+1) = −3.6
  EXPECT_DOUBLE_EQ(target_psd(s, 20.0), std::pow(4.0, -3.6));
  EXPECT_EQ(target_psd(s, 20.001), 0.0);
}

TEST(SurfaceGenerator, MeanHeightIsZero) {
  const RealField h = generate_surface(spec_on(Grid2D::square(128, 1.0), 0.5, 2.0, 2.0, 32.0));
  EXPECT_LE(std::abs(mean_height(h)), 1e-14 * h_rms(h));
}

TEST(SurfaceGenerator, SameSeedGivesTheSameSurfaceAnotherSeedAnother) {
  const Grid2D g = Grid2D::square(64, 1.0);
  const RealField a = generate_surface(spec_on(g, 0.7, 2.0, 2.0, 16.0, 42));
  const RealField b = generate_surface(spec_on(g, 0.7, 2.0, 2.0, 16.0, 42));
  const RealField c = generate_surface(spec_on(g, 0.7, 2.0, 2.0, 16.0, 43));
  for (std::size_t k = 0; k < a.size(); ++k) ASSERT_EQ(a[k], b[k]);
  // Different phases: the two surfaces are nearly uncorrelated (|ρ| well below 1).
  double ac = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) ac += a[k] * c[k];
  const double rho = ac / static_cast<double>(a.size()) / (h_rms(a) * h_rms(c));
  EXPECT_LT(std::abs(rho), 0.5);
}

// Fit band: n = 256, k_l = k_r = 4, k_s = 64 (= n/4: four points per shortest
// wavelength, a 16× band). The radial bins [k, k+1) for k = 4 … 63 lie wholly inside
// [k_l, k_s], so no bin averages in the empty modes outside the band; the band is
// therefore q = 2π·4/L … 2π·64/L (bin 64 holds only the modes with |k| = 64 exactly,
// its mean |q| is above 2π·64/L and it is left out).
class SurfaceHurstRecovery : public ::testing::TestWithParam<double> {};

TEST_P(SurfaceHurstRecovery, FitOnTheRadialPsdRecoversHWithin005) {
  const double hurst = GetParam();
  const double l = 1e-4;
  const auto s = spec_on(Grid2D::square(256, l), hurst, 4.0, 4.0, 64.0, 7);
  const RadialPsd radial = radial_psd(psd_2d(generate_surface(s, RoughnessMeasure::HPrimeRms, 0.1)));
  const HurstFit fit = fit_hurst(radial, 2.0 * pi * 4.0 / l, 2.0 * pi * 64.0 / l);
  std::cout << "H = " << hurst << ": fitted " << fit.hurst << " ± " << fit.hurst_error << " on " << fit.points
            << " bins\n";
  EXPECT_EQ(fit.points, 60u);
  EXPECT_NEAR(fit.hurst, hurst, 0.05);
}

INSTANTIATE_TEST_SUITE_P(Hurst, SurfaceHurstRecovery, ::testing::Values(0.3, 0.5, 0.8));

TEST(SurfaceGenerator, PlateauDoesNotBiasTheFitAboveRollOff) {
  const double l = 1.0;
  const auto s = spec_on(Grid2D::square(256, l), 0.5, 2.0, 8.0, 64.0, 3);
  const HurstFit fit = fit_hurst(radial_psd(psd_2d(generate_surface(s))), 2.0 * pi * 8.0 / l, 2.0 * pi * 64.0 / l);
  EXPECT_NEAR(fit.hurst, 0.5, 0.05);
}

TEST(SurfaceGenerator, RescaledToATargetRoughnessHitsIt) {
  const auto s = spec_on(Grid2D::square(128, 1e-4), 0.8, 4.0, 4.0, 32.0);
  for (const auto& [measure, target] : {std::pair{RoughnessMeasure::HPrimeRms, 0.15},
                                        std::pair{RoughnessMeasure::HRms, 2e-7},
                                        std::pair{RoughnessMeasure::Sa, 0.79e-6}}) {
    const RealField h = generate_surface(s, measure, target);
    EXPECT_NEAR(roughness(h, measure) / target, 1.0, 1e-12) << name(measure);
  }
}

TEST(SurfaceGenerator, RefusesParametersOutsideTheirRangeByName) {
  const Grid2D g = Grid2D::square(256, 1.0);
  EXPECT_THAT(rejection(spec_on(g, 0.0, 4, 4, 64)), HasSubstr("'hurst'"));
  EXPECT_THAT(rejection(spec_on(g, -0.2, 4, 4, 64)), HasSubstr("'hurst'"));
  EXPECT_THAT(rejection(spec_on(g, 1.2, 4, 4, 64)), HasSubstr("(0, 1]"));
  EXPECT_THAT(rejection(spec_on(g, 0.8, 4, 4, 200)), HasSubstr("'k_s' = 200"));
  EXPECT_THAT(rejection(spec_on(g, 0.8, 4, 4, 200)), HasSubstr("Nyquist"));
  EXPECT_THAT(rejection(spec_on(g, 0.8, 4, 4, 200)), HasSubstr("128"));
  EXPECT_THAT(rejection(spec_on(g, 0.8, 80, 80, 64)), HasSubstr("'k_s' = 64"));  // k_l > k_s
  EXPECT_THAT(rejection(spec_on(g, 0.8, 0, 4, 64)), HasSubstr("'k_l' = 0"));
  EXPECT_THAT(rejection(spec_on(g, 0.8, 8, 4, 64)), HasSubstr("'k_r' = 4"));
  EXPECT_THAT(rejection(spec_on(Grid2D::square(3, 1.0), 0.8, 1, 1, 1)), HasSubstr("'grid'"));
  EXPECT_THAT(rejection(spec_on(Grid2D(64, 64, 0.0, 1.0), 0.8, 1, 1, 8)), HasSubstr("'lx'"));
  EXPECT_EQ(rejection(spec_on(g, 1.0, 4, 4, 128)), "(accepted)");  // the bounds themselves are allowed
}

TEST(SurfaceGenerator, SphereIsAnExactSphericalCapSummitUp) {
  const double r = 0.3;
  const Grid2D g = Grid2D::square(100, 1.0);
  const RealField h = sphere(g, r, g.x(50), g.y(50));
  EXPECT_EQ(h(50, 50), 0.0);  // the summit, the highest point
  EXPECT_EQ(*std::max_element(h.begin(), h.end()), 0.0);
  const double d = std::hypot(g.x(60) - g.x(50), g.y(45) - g.y(50));
  EXPECT_NEAR(h(60, 45), std::sqrt(r * r - d * d) - r, 1e-15);
  EXPECT_EQ(h(0, 0), -r);  // beyond the rim: clipped to the rim height
}

TEST(SurfaceGenerator, SphereCentredOnACornerWrapsAroundThePeriodicCell) {
  const Grid2D g = Grid2D::square(64, 1.0);
  const RealField h = sphere(g, 0.2, 0.0, 0.0);
  const double dx = g.dx();
  EXPECT_EQ(h(0, 0), 0.0);
  EXPECT_NEAR(h(63, 0), std::sqrt(0.04 - dx * dx) - 0.2, 1e-14);  // one cell to the left, through the edge
  EXPECT_NEAR(h(63, 63), h(1, 1), 1e-14);
  EXPECT_THROW(sphere(g, 0.0, 0.5, 0.5), InputError);
}

TEST(SurfaceGenerator, PlanesAndSumsArePointwise) {
  const Grid2D g(16, 8, 2.0, 1.0);
  const RealField h = add(tilted_plane(g, 0.1, -0.3), plane(g, 2.5));
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) ASSERT_DOUBLE_EQ(h(i, j), 0.1 * g.x(i) - 0.3 * g.y(j) + 2.5);
  EXPECT_THROW(add(plane(g, 1.0), plane(Grid2D(16, 8, 1.0, 1.0), 1.0)), InputError);
}
