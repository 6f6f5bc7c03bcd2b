#include "wearscale/dem/rough_profile.hpp"

#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "wearscale/core/errors.hpp"
#include "wearscale/dem/random.hpp"
#include "wearscale/dem/surface_roughness.hpp"

namespace wearscale::dem {

namespace {
// Heights on a grid fine enough for the shortest mode (the Sa scaling).
constexpr int samples_per_wavelength = 32;
}  // namespace

RoughProfile::RoughProfile(const RoughProfileSpec& s) : length_(s.length) {
  auto refuse = [](const char* what, double v, const char* allowed) {
    throw InputError(fmt::format("rough profile: {} = {}; allowed: {}", what, v, allowed));
  };
  if (!(s.length > 0.0) || !std::isfinite(s.length)) refuse("length L", s.length, "> 0");
  if (!(s.sa >= 0.0) || !std::isfinite(s.sa)) refuse("Sa", s.sa, "≥ 0");
  if (!(s.hurst > 0.0 && s.hurst <= 1.0)) refuse("Hurst exponent", s.hurst, "0 < H ≤ 1");
  if (s.k_min < 1) refuse("k_min", s.k_min, "≥ 1");
  if (s.k_max < s.k_min) refuse("k_max", s.k_max, "≥ k_min");
  Random rng(s.seed);
  for (int k = s.k_min; k <= s.k_max; ++k) {
    const double q = 2.0 * std::numbers::pi * k / s.length;
    wavenumber_.push_back(q);
    amplitude_.push_back(std::pow(q, -(s.hurst + 0.5)));  // √(C(q)), C ∝ q^−(1+2H)
    phase_.push_back(rng.uniform(0.0, 2.0 * std::numbers::pi));
  }
  const int n = samples_per_wavelength * s.k_max;
  std::vector<double> h(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) h[static_cast<std::size_t>(i)] = (*this)(s.length * i / n);
  const double sa = arithmetic_roughness(h);
  for (double& a : amplitude_) a *= sa > 0.0 ? s.sa / sa : 0.0;
}

double RoughProfile::operator()(double x) const {
  double h = 0.0;
  for (std::size_t k = 0; k < wavenumber_.size(); ++k) h += amplitude_[k] * std::cos(wavenumber_[k] * x + phase_[k]);
  return h;
}

}  // namespace wearscale::dem
