#include "wearscale/materials/material.hpp"

#include <numbers>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::materials {

Material silicon() {
  Material m;
  m.name = "Si";
  m.young = 150e9;  // Hopcroft et al. (2010), averaged over directions
  m.poisson = 0.27;
  m.density = 2330.0;
  m.surface_energy = 1.2;
  m.tensile_strength = 21e9;
  m.shear_strength = 11e9;
  m.interatomic = silicon_model();
  m.source = "thesis Table 2.1 (crystalline Si, direction-averaged)";
  return m;
}

Material silica() {
  Material m;
  m.name = "SiO2";
  m.young = 73e9;
  m.poisson = 0.17;
  m.density = 2200.0;
  m.surface_energy = 1.5;
  m.tensile_strength = 16e9;  // Luo et al. (2016)
  m.shear_strength = 9e9;
  m.restitution = 0.9;
  m.interatomic = silica_model();
  m.source = "thesis Table 2.1 and Table 6.5 (amorphous SiO2)";
  return m;
}

double effective_modulus(const Material& a, const Material& b) {
  return 1.0 / ((1.0 - a.poisson * a.poisson) / a.young + (1.0 - b.poisson * b.poisson) / b.young);  // (1.12)
}

double geometric_factor(JunctionGeometry geometry, double poisson) {
  switch (geometry) {
    case JunctionGeometry::FlatCircular: return 12.0 * std::numbers::pi / (2.0 - poisson);  // (4.35)
    case JunctionGeometry::CollidingAsperities: return 12.0;                                  // (8.3)
    case JunctionGeometry::DemCylinder: return 32.0;                                          // (6.65)
  }
  return 0.0;
}

double critical_size(const Material& m, double junction_strength, JunctionGeometry geometry) {
  if (!(junction_strength > 0.0))
    throw InputError(fmt::format("critical size of {}: junction strength {} Pa is not allowed; allowed: > 0", m.name,
                                 junction_strength));
  return geometric_factor(geometry, m.poisson) * m.surface_energy * m.shear_modulus() /
         (junction_strength * junction_strength);
}

MaterialLibrary::MaterialLibrary() {
  add(silicon());
  add(silica());
}

void MaterialLibrary::add(Material m) {
  const std::string name = m.name;
  by_name_.insert_or_assign(name, std::move(m));
}

const Material& MaterialLibrary::get(const std::string& name) const {
  if (auto it = by_name_.find(name); it != by_name_.end()) return it->second;
  throw InputError(fmt::format("unknown material '{}'; known materials: {} (define others in [materials.define.<name>])",
                               name, fmt::join(names(), ", ")));
}

std::vector<std::string> MaterialLibrary::names() const {
  std::vector<std::string> out;
  for (const auto& [n, m] : by_name_) out.push_back(n);
  return out;
}

}  // namespace wearscale::materials
