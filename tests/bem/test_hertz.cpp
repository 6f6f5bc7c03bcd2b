// Hertz contact of the thesis' pin (§8.1; the thesis is cited in docs/references.md): SiO2 sphere of
// R = 3 mm on SiO2 at F = 1 N → E* = 37.6 GPa, a = 39.1 µm (2a = 78.2 µm), p0 = 312 MPa.
#include <gtest/gtest.h>

#include <numbers>

#include "wearscale/bem/hertz.hpp"

using namespace wearscale::bem;

namespace {
const double e_star = effective_modulus(73e9, 0.17, 73e9, 0.17);
const HertzContact pin{3e-3, 1.0, e_star};
}  // namespace

TEST(Hertz, EffectiveModulusOfSiO2OnSiO2) {
  EXPECT_NEAR(e_star, 37.6e9, 0.05e9);  // E/(2(1−ν²)), quoted to 3 digits
}

TEST(Hertz, PinContactRadiusMatchesTheThesis) {
  EXPECT_NEAR(pin.contact_radius(), 39.1e-6, 0.05e-6);
  EXPECT_NEAR(2.0 * pin.contact_radius(), 78.2e-6, 0.1e-6);
}

TEST(Hertz, PinPeakPressureMatchesTheThesis) { EXPECT_NEAR(pin.peak_pressure(), 312e6, 0.5e6); }

TEST(Hertz, PressureIntegratesToTheLoad) {
  // ∫ p dA = 2π ∫ p(r) r dr = F, midpoint rule on 20000 rings.
  const double a = pin.contact_radius();
  const int n = 20000;
  double f = 0.0;
  for (int k = 0; k < n; ++k) {
    const double r = (k + 0.5) * a / n;
    f += 2.0 * std::numbers::pi * r * pin.pressure(r) * a / n;
  }
  EXPECT_NEAR(f, pin.load, 1e-6);
  EXPECT_EQ(pin.pressure(1.01 * a), 0.0);
}

TEST(Hertz, ApproachAndMeanPressureFollowFromTheRadius) {
  const double a = pin.contact_radius();
  EXPECT_DOUBLE_EQ(pin.approach(), a * a / pin.radius);
  EXPECT_NEAR(pin.mean_pressure(), 2.0 / 3.0 * pin.peak_pressure(), 1e-6);
}
