#include "wearscale/coupling/shear_test_keys.hpp"

#include <cmath>
#include <cstdlib>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/cache_folder.hpp"
#include "wearscale/io/material_definitions.hpp"
#include "wearscale/md/result_cache.hpp"

namespace wearscale::coupling {

using namespace md;

ShearTestSpec read_shear_test_spec(const Config& root) {
  const Config c = root.section("md");
  materials::MaterialLibrary library;
  define_materials_from(library, root);
  const std::string material = c.string("material");
  if (!library.contains(material))
    throw c.error("material", "unknown material",
                  fmt::format("{} or a [materials.define.<name>] table with an interatomic model",
                              fmt::join(library.names(), ", ")));
  const auto& record = library.get(material);
  if (!record.interatomic)
    throw c.error("material", "the material has no interatomic model for the MD shear test",
                  fmt::format("a [materials.define.{}.interatomic] table (pair_style, potential, elements, masses, "
                              "structure, lattice_constant)",
                              material));
  return read_shear_test_spec(c, material, *record.interatomic);
}

namespace {

// The protocol keys present in table `c` override `s` (the *_or getters take
// the current value as fallback: every key is "read", so a misspelt one gets a
// "did you mean" suggestion).
void apply_protocol_keys(const Config& c, const std::string& material, const materials::InteratomicModel& model,
                         ShearTestSpec& s) {
  const units::Dimension rate = units::temperature / units::time;
  auto number = [](const Config& t, const char* key, double& v, const Range& r, units::Dimension dim) {
    v = t.number_or(key, v, r, dim);
  };
  c.mark_used("pressures");
  if (c.has("pressures")) s.pressures = c.numbers("pressures", Range::non_negative(), units::pressure);
  number(c, "lateral_size", s.lateral_size, Range::positive(), units::length);
  number(c, "height", s.height, Range::positive(), units::length);
  number(c, "wall_thickness", s.wall_thickness, Range::positive(), units::length);
  number(c, "thermostat_thickness", s.thermostat_thickness, Range::positive(), units::length);
  number(c, "shear_velocity", s.shear_velocity, Range::positive(), units::velocity);
  number(c, "temperature", s.temperature, Range::positive(), units::temperature);
  number(c, "langevin_damp", s.langevin_damp, Range::positive(), units::time);
  number(c, "timestep", s.timestep, Range::open_closed(0.0, 1e-14), units::time);
  number(c, "compression_time", s.compression_time, Range::non_negative(), units::time);
  number(c, "strain_end", s.strain_end, Range::open_closed(0.0, 10.0), units::dimensionless);
  c.mark_used("window");
  if (c.has("window")) {
    const auto w = c.numbers("window", Range::closed(0.0, 10.0));
    if (w.size() != 2) throw c.error("window", fmt::format("{} values", w.size()), "[begin, end] strains");
    s.window_begin = w[0];
    s.window_end = w[1];
  }
  s.sample_steps = c.integer_or("sample_steps", s.sample_steps, Range::closed(1, 1e7));
  s.seed = static_cast<std::uint32_t>(c.integer_or("seed", s.seed, Range::closed(1, 9e8)));
  number(c, "modulus_strain", s.modulus_strain, Range::open(0.0, 1.0), units::dimensionless);
  s.lmp = c.string_or("lmp", s.lmp);
  s.ranks = static_cast<int>(c.integer_or("ranks", s.ranks, Range::closed(1, 1024)));
  s.use_cache = c.boolean_or("cache", s.use_cache);
  if (const std::string dir = c.string_or("cache_dir", ""); !dir.empty()) s.cache_dir = expand_home(dir);
  if (c.has("quench")) {
    const Config q = c.section("quench");
    if (!model.amorphous)
      throw c.error("quench", fmt::format("a melt-quench applies to an amorphous sample; {} is a crystal", material),
                    "an amorphous material (SiO2, or interatomic.amorphous = true)");
    auto& qs = s.quench;
    q.mark_used("temperatures");
    if (q.has("temperatures")) qs.temperatures = q.numbers("temperatures", Range::positive(), units::temperature);
    number(q, "hold_time", qs.hold_time, Range::positive(), units::time);
    number(q, "cooling_rate", qs.cooling_rate, Range::positive(), rate);
    number(q, "final_cooling_rate", qs.final_cooling_rate, Range::positive(), rate);
    number(q, "timestep", qs.timestep, Range::open_closed(0.0, 1e-14), units::time);
    number(q, "pressure", qs.pressure, Range::any(), units::pressure);
    number(q, "barostat_damp", qs.barostat_damp, Range::positive(), units::time);
    number(q, "bulk_modulus", qs.bulk_modulus, Range::positive(), units::pressure);
    number(q, "thermostat_damp", qs.thermostat_damp, Range::positive(), units::time);
    qs.constant_volume = q.boolean_or("constant_volume", qs.constant_volume);
  }
}

}  // namespace

ShearTestSpec read_shear_test_spec(const Config& c, const std::string& material,
                                   const materials::InteratomicModel& declared) {
  // A table named after the material holds keys for it alone ([scale.molecular.Cu] strain_end = 0.5).
  const bool own = c.has(material) && !c.section(material).keys().empty();
  const Config mine = c.section(material);
  // The model's own keys a case may override here (the [md] keys of the SiO2 and Si tests).
  materials::InteratomicModel model = declared;
  for (const Config* t : {&c, &mine}) {
    if (t == &mine && !own) break;
    if (t->has("potential")) model.potential = potential_file(*t, "potential");
    model.lattice_constant = t->number_or("lattice_constant", model.lattice_constant, Range::positive(), units::length);
    model.cutoff = t->number_or("cutoff", model.cutoff, Range::non_negative(), units::length);
    if (t->has("cutoff") && model.pair_style != "vashishta")
      throw t->error("cutoff", fmt::format("{} takes its cutoff from the potential file (pair_style {})", material,
                                           model.pair_style),
                     "a cutoff for pair_style vashishta only");
  }
  ShearTestSpec s;
  try {
    s = preset_spec(material, model, c.choice_or("preset", "smoke", {"smoke", "thesis"}));
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: [md]: {}", c.source(), e.what()));
  }
  s.pressures.clear();
  apply_protocol_keys(c, material, model, s);
  if (own) apply_protocol_keys(mine, material, model, s);
  if (s.pressures.empty()) (void)c.numbers("pressures", Range::non_negative(), units::pressure);  // the error: missing
  // Consistency between keys (window inside the strain range, walls vs box, …).
  try {
    validate(s);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: [md]: {}", c.source(), e.what()));
  }
  return s;
}

}  // namespace wearscale::coupling
