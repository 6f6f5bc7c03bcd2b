#include "wearscale/bem/hertz.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace wearscale::bem {

double effective_modulus(double e1, double nu1, double e2, double nu2) {
  if (!(e1 > 0) || !(e2 > 0)) throw std::invalid_argument("effective_modulus: Young's moduli must be > 0");
  return 1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2);  // (1.12)
}

double HertzContact::contact_radius() const { return std::cbrt(3.0 * load * radius / (4.0 * e_star)); }

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
