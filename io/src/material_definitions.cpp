#include "wearscale/io/material_definitions.hpp"

#include <utility>

#include "wearscale/core/units.hpp"

namespace wearscale {

void define_materials_from(materials::MaterialLibrary& library, const Config& root) {
  const Config defs = root.section("materials.define");
  for (const auto& name : root.keys("materials.define")) {
    const Config c = defs.section(name);
    materials::Material m;
    m.name = name;
    m.young = c.number("young", Range::positive(), units::pressure);
    m.poisson = c.number("poisson", Range::open_closed(-1.0, 0.5));
    m.density = c.number("density", Range::positive(), units::density);
    m.surface_energy = c.number("surface_energy", Range::positive(), units::surface_energy);
    m.tensile_strength = c.number("tensile_strength", Range::positive(), units::pressure);
    m.shear_strength = c.number("shear_strength", Range::positive(), units::pressure);
    if (c.has("restitution")) m.restitution = c.number("restitution", Range::open_closed(0.0, 1.0));
    m.source = c.string_or("source", "defined in " + root.source());
    library.add(std::move(m));
  }
}

}  // namespace wearscale
