#include "wearscale/wear/energy_balance.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::wear {

double adhesive_energy(double diameter, double surface_energy) {
  return std::numbers::pi * surface_energy * diameter * diameter;  // (4.16)
}

double single_contact_elastic_energy(double diameter, double traction, double shear_modulus, double poisson) {
  return (2.0 - poisson) * diameter * diameter * diameter * traction * traction / (12.0 * shear_modulus);  // (4.33)
}

double critical_diameter(double surface_energy, double shear_modulus, double poisson, double junction_strength) {
  auto positive = [](const char* name, double v) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw InputError(fmt::format("critical diameter d*: {} = {} is not allowed; allowed: > 0", name, v));
  };
  positive("surface energy γ", surface_energy);
  positive("shear modulus G", shear_modulus);
  positive("junction strength σ_j", junction_strength);
  if (!(poisson > -1.0 && poisson <= 0.5))
    throw InputError(fmt::format("critical diameter d*: Poisson's ratio ν = {} is not allowed; allowed: −1 < ν ≤ 0.5",
                                 poisson));
  return 12.0 * std::numbers::pi * surface_energy * shear_modulus /
         ((2.0 - poisson) * junction_strength * junction_strength);  // (4.35)
}

}  // namespace wearscale::wear
