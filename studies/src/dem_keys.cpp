#include "dem_keys.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/dem/contact_law.hpp"
#include "wearscale/dem/engine.hpp"
#ifdef WEARSCALE_DEM_LAMMPS
#include "wearscale/dem/lammps_engine.hpp"
#endif
#include "wearscale/dem/patch_test.hpp"
#include "wearscale/io/material_definitions.hpp"
#include "wearscale/materials/material.hpp"

namespace wearscale::studies {

using namespace dem;

void require_engine([[maybe_unused]] const Config& c, const std::string& engine) {
#ifdef WEARSCALE_DEM_LAMMPS
  if (engine == "lammps") register_lammps_engine();
#else
  if (engine == "lammps")
    throw c.error("engine", "this build has no LAMMPS engine (it is built when CMake finds Debian's liblammps-dev, "
                  "option WEARSCALE_DEM_LAMMPS)", "wearscale");
#endif
}

KeyTable<DemKeys> dem_table(const DemTableOptions& options) {
  using K = DemKeys;
  KeyTable<K> t;
  t.string("material", &K::material, options.materials).flag("--material");
  if (options.default_material != nullptr) {
    const std::string name = options.default_material;
    t.computed_text([name](const K&) { return name; }, name);
  }
  // ν read over all ν > −1 so that ν in (1/4, 1/2] meets the reason of dem_material, not "(-1, 0.5)".
  t.optional_number("poisson", &K::poisson, Range::greater_than(-1.0), units::dimensionless, "target Poisson's ratio")
      .allowed("(-1, 0.25]")
      .fallback("the material's")
      .flag(options.poisson_flag)
      .optional_number("restitution", &K::restitution, Range::open_closed(0.0, 1.0), units::dimensionless,
                       "coefficient of restitution")
      .fallback("the material's")
      .number("scaling_exponent", &K::scaling_exponent, Range::closed(0.0, 1.0), "size-scaling exponent s of (6.57)")
      .flag(options.scaling_exponent_flag)
      // An unknown law named with the registered ones, in name order.
      .then([](const Config& c, K&) {
        if (!c.has("law")) return;
        const std::string law = c.string("law");
        const auto known = contact_law_names();
        if (std::find(known.begin(), known.end(), law) == known.end())
          throw c.error("law", fmt::format("unknown DEM contact law '{}'", law), fmt::format("{}", fmt::join(known, ", ")));
      })
      .choice("law", &K::law, contact_law_names(), "contact law between the particles (contact_law.hpp)");
  // A study of the cohesive law's strengths refuses another law (and reads no friction).
  if (options.cohesive_study != nullptr) {
    const std::string study = options.cohesive_study;
    t.then([study](const Config& c, K& k) {
      if (k.law != "cohesive")
        throw c.error("law", fmt::format("the {} measures the cohesive law's strengths", study), "cohesive");
    });
  } else {
    t.number("friction", &K::friction, Range::non_negative(), "Coulomb μ of the hooke law")
        .read_if([](const Config&, const K& k) { return k.law == "hooke"; });
  }
  t.choice("engine", &K::engine, std::vector<std::string>{"wearscale", "lammps"},
           "the engine that integrates the particles (LAMMPS: over every rank under mpirun)")
      .then([](const Config& c, K& k) { require_engine(c, k.engine); });
  if (options.history)
    t.choice("history", &K::history_of_touching_pairs_only,
             std::vector<std::pair<std::string, bool>>{{"kept", false}, {"touching", true}},
             "tangential histories over neighbour rebuilds: kept for every pair in reach (6.4), or for touching "
             "pairs only (the thesis' LAMMPS runs)");
  return t;
}

CohesiveMaterial dem_material(const Config& root, const DemKeys& k) {
  const Config c = root.section("dem");
  CohesiveMaterial m;
  if (k.material == "table-6.4") {
    m = patch_test_targets();
    m.scaling_exponent = k.scaling_exponent;
  } else {
    materials::MaterialLibrary library;
    define_materials_from(library, root);
    if (!library.contains(k.material)) {
      std::string known = "table-6.4";
      for (const auto& n : library.names()) known += ", " + n;
      throw c.error("material", fmt::format("unknown material '{}'", k.material), known);
    }
    try {
      m = cohesive_material(library.get(k.material), k.scaling_exponent, k.restitution);
    } catch (const InputError& e) {
      throw c.error("restitution", e.what(), "0 < η ≤ 1");
    }
  }
  if (k.restitution) m.restitution = *k.restitution;
  if (k.poisson) m.poisson = *k.poisson;
  if (!(m.poisson <= 0.25))
    throw c.error("poisson",
                  fmt::format("ν = {} cannot be modelled by the DEM pair force: central pair forces give ν ≤ 1/4 "
                              "(the tangential cross section A_T of (6.52) would be negative)",
                              m.poisson),
                  "-1 < ν ≤ 0.25");
  require_modelled(m);
  return m;
}

void with_dem(const DemInputs& dem, SlidingCellSpec& cell) {
  cell.material = dem.material;
  cell.law = dem.keys.law;
  cell.friction = dem.keys.friction;
  cell.history_of_touching_pairs_only = dem.keys.history_of_touching_pairs_only;
  cell.engine = dem.keys.engine;
}

}  // namespace wearscale::studies
