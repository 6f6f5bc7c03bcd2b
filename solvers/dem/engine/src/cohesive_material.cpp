#include "wearscale/dem/cohesive_material.hpp"

#include <cmath>
#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::dem {

CohesiveMaterial patch_test_targets() { return {"table-6.4", 1.0, 0.15, 0.2, 0.1, 1.5, 0.95, 1.0, 0.5}; }

CohesiveMaterial cohesive_material(const materials::Material& m, double scaling_exponent,
                                   std::optional<double> restitution) {
  CohesiveMaterial c;
  c.name = m.name;
  c.young = m.young;
  c.poisson = m.poisson;
  c.tensile_strength = m.tensile_strength;
  c.shear_strength = m.shear_strength;
  c.surface_energy = m.surface_energy;
  c.density = m.density;
  c.scaling_exponent = scaling_exponent;
  if (restitution) {
    c.restitution = *restitution;
  } else if (m.restitution) {
    c.restitution = *m.restitution;
  } else {
    throw InputError(fmt::format(
        "material '{}' has no restitution coefficient η, which the DEM damping (6.59) needs; "
        "give one (restitution = 0.9, allowed: 0 < η ≤ 1)",
        m.name));
  }
  return c;
}

std::string why_not_modelled(const CohesiveMaterial& m) {
  if (!(m.poisson <= 0.25))
    return fmt::format(
        "material '{}': Poisson's ratio ν = {} cannot be modelled by the DEM pair force; allowed: "
        "-1 < ν ≤ 0.25. Central pair forces give ν ≤ 1/4 (the tangential cross section A_T of "
        "(6.52) would be negative); use ν ≤ 0.25 and accept the error on ν, or a model with "
        "many-body forces",
        m.name, m.poisson);
  if (!(m.poisson > -1.0))
    return fmt::format("material '{}': Poisson's ratio ν = {}; allowed: -1 < ν ≤ 0.25", m.name,
                       m.poisson);
  auto positive = [&](double v, const char* what) -> std::string {
    if (v > 0.0 && std::isfinite(v)) return {};
    return fmt::format("material '{}': {} = {}; allowed: > 0", m.name, what, v);
  };
  for (const auto& problem : {positive(m.young, "Young's modulus E"),
                              positive(m.tensile_strength, "tensile strength σ_m,N"),
                              positive(m.shear_strength, "shear strength σ_m,T"),
                              positive(m.surface_energy, "surface energy γ"),
                              positive(m.density, "density ρ")})
    if (!problem.empty()) return problem;
  if (!(m.restitution > 0.0 && m.restitution <= 1.0))
    return fmt::format("material '{}': restitution η = {}; allowed: 0 < η ≤ 1", m.name,
                       m.restitution);
  if (!(m.scaling_exponent >= 0.0 && m.scaling_exponent <= 1.0))
    return fmt::format("material '{}': scaling exponent s = {}; allowed: 0 ≤ s ≤ 1", m.name,
                       m.scaling_exponent);
  return {};
}

void require_modelled(const CohesiveMaterial& m) {
  if (auto problem = why_not_modelled(m); !problem.empty()) throw InputError(problem);
}

double critical_diameter(const CohesiveMaterial& m) {
  return 4.0 * m.surface_energy * m.young / (m.tensile_strength * m.tensile_strength);  // (6.35)
}

double critical_junction_size(const CohesiveMaterial& m) {
  const double shear_modulus = m.young / (2.0 * (1.0 + m.poisson));
  return materials::geometric_factor(materials::JunctionGeometry::DemCylinder, m.poisson) * m.surface_energy *
         shear_modulus / (m.shear_strength * m.shear_strength);  // (6.65)
}

double minimum_diameter(const CohesiveMaterial& m) {
  return 4.0 * m.surface_energy / m.tensile_strength;  // (6.62)
}

CohesiveMaterial mix(const CohesiveMaterial& a, const CohesiveMaterial& b) {
  if (a.name == b.name) return a;
  CohesiveMaterial c;
  c.name = a.name + "/" + b.name;
  c.young = 2.0 * a.young * b.young / (a.young + b.young);
  c.poisson = 0.5 * (a.poisson + b.poisson);
  c.tensile_strength = std::min(a.tensile_strength, b.tensile_strength);
  c.shear_strength = std::min(a.shear_strength, b.shear_strength);
  c.surface_energy = std::sqrt(a.surface_energy * b.surface_energy);
  c.restitution = 0.5 * (a.restitution + b.restitution);
  c.density = 0.5 * (a.density + b.density);
  c.scaling_exponent = 0.5 * (a.scaling_exponent + b.scaling_exponent);
  return c;
}

}  // namespace wearscale::dem
