#include "wearscale/bem/hertz.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::bem {

double effective_modulus(double e1, double nu1, double e2, double nu2) {
  for (const double e : {e1, e2})
    if (!(e > 0.0 && std::isfinite(e)))
      throw InputError(fmt::format("effective modulus: Young's modulus E = {:g}; allowed: finite and > 0", e));
  for (const double nu : {nu1, nu2})
    if (!(nu > -1.0 && nu <= 0.5))
      throw InputError(fmt::format("effective modulus: Poisson's ratio ν = {:g}; allowed: −1 < ν ≤ 0.5", nu));
  return 1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2);  // (1.12)
}

void HertzContact::check() const {
  const auto positive = [](double v, const char* what, const char* unit) {
    if (!(v > 0.0 && std::isfinite(v)))
      throw InputError(fmt::format("Hertz contact: {} = {:g} {}; allowed: finite and > 0", what, v, unit));
  };
  positive(radius, "radius R", "m");
  positive(load, "load F", "N");
  positive(e_star, "contact modulus E*", "Pa");
}

double HertzContact::contact_radius() const {
  check();
  return std::cbrt(3.0 * load * radius / (4.0 * e_star));
}

double HertzContact::peak_pressure() const {
  const double a = contact_radius();
  return 3.0 * load / (2.0 * std::numbers::pi * a * a);
}

double HertzContact::mean_pressure() const {
  const double a = contact_radius();
  return load / (std::numbers::pi * a * a);
}

double HertzContact::approach() const {
  const double a = contact_radius();
  return a * a / radius;
}

double HertzContact::pressure(double r) const {
  const double a = contact_radius();
  if (std::abs(r) >= a) return 0.0;
  return peak_pressure() * std::sqrt(1.0 - (r * r) / (a * a));
}

}  // namespace wearscale::bem
