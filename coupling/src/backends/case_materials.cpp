#include "backends/case_materials.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/coupling/backend_keys.hpp"
#include "wearscale/io/material_definitions.hpp"

namespace wearscale::coupling {

const KeyTable<CaseMaterialKeys>& case_material_keys() {
  using K = CaseMaterialKeys;
  static const auto table =
      KeyTable<K>()
          .string("pin", &K::pin, "material of the pin (a built-in record or a [materials.define.<name>] table)")
          .required()
          .string("disc", &K::disc, "material of the disc (the substrate under its layer)")
          .required()
          .string("layer.material", &K::layer_material, "material of the disc's surface layer (its oxide)")
          .computed_text([](const K& k) { return k.disc; }, "the disc's")
          .number("layer.thickness", &K::layer_thickness, Range::non_negative().or_infinite(), units::length,
                  "thickness h of the layer; inf: the layer's material in bulk")
          .required()
          .read_if([](const Config& c, const K&) { return c.has("layer"); })
          .fallback("0 without a [materials.layer] table; required in one");
  return table;
}

const KeyTable<StrengthLawKeys>& strength_law_keys() {
  using K = StrengthLawKeys;
  static const auto table = KeyTable<K>().choice(
      "outside", &K::outside,
      std::vector<std::pair<std::string, materials::OutsideTable>>{{"error", materials::OutsideTable::Error},
                                                                   {"clamp", materials::OutsideTable::Clamp}},
      "a pressure outside a table: an error, or the nearest end's strengths");
  return table;
}

Schema materials_schema() { return case_material_keys().schema("materials"); }

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
