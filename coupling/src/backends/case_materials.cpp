#include "backends/case_materials.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/io/material_definitions.hpp"

namespace wearscale::coupling {

materials::MaterialLibrary material_library(const Config& root) {
  materials::MaterialLibrary library;
  define_materials_from(library, root);
  return library;
}

std::vector<std::string> case_materials(const Config& root, const materials::MaterialLibrary& library) {
  std::vector<std::string> names;
  for (const char* key : {"materials.pin", "materials.disc", "materials.layer.material"}) {
    if (!root.has(key)) continue;
    const std::string name = root.string(key);
    if (!library.contains(name))
      throw root.error(key, "unknown material", fmt::format("{} or a [materials.define.<name>] table",
                                                             fmt::join(library.names(), ", ")));
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  if (names.empty())
    throw root.error("materials.pin", "the case names no material ([materials] pin, disc, layer)",
                     "a material name, e.g. pin = \"SiO2\"");
  return names;
}

void publish_strength(Exchange& exchange, RunContext& ctx, const std::string& material, materials::StrengthLaw law,
                      Provenance provenance) {
  const auto& t = law.table();
  const std::string group = "/molecular/" + material;
  ctx.h5().write_table(group, {"pressure", "sigma_max", "sigma_dyn"}, {t.pressure, t.sigma_max, t.sigma_dyn},
                       {"Pa", "Pa", "Pa"});
  ctx.h5().set_attribute(group, "file", t.origin);
  for (const auto& [k, v] : t.provenance) ctx.h5().set_attribute(group, k, v);
  provenance.parameters["table"] = t.origin;
  provenance.parameters["material"] = material;
  exchange.put<Quantity::ShearStrength>(material, std::move(law), std::move(provenance));
}

}  // namespace wearscale::coupling
