#include "wearscale/coupling/shear_test_keys.hpp"

#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "wearscale/core/cache_folder.hpp"
#include "wearscale/md/result_cache.hpp"

namespace wearscale::coupling {

using namespace md;

ShearTestSpec read_shear_test_spec(const Config& config) {
  const Config c = config.section("md");
  return read_shear_test_spec(c, c.choice("material", {"Si", "SiO2"}));
}

ShearTestSpec read_shear_test_spec(const Config& c, const std::string& material_name) {
  const Material material = material_from_string(material_name);
  ShearTestSpec s = preset_spec(material, c.choice_or("preset", "smoke", {"smoke", "thesis"}));
  const units::Dimension rate = units::temperature / units::time;

  s.pressures = c.numbers("pressures", Range::non_negative(), units::pressure);
  // *_or getters with the preset's value as fallback: every key is "read",
  // so a misspelt one gets a "did you mean" suggestion.
  auto number = [](const Config& t, const char* key, double& v, const Range& r, units::Dimension dim) {
    v = t.number_or(key, v, r, dim);
  };
  number(c, "lateral_size", s.lateral_size, Range::positive(), units::length);
  number(c, "height", s.height, Range::positive(), units::length);
  number(c, "lattice_constant", s.lattice_constant, Range::positive(), units::length);
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
  if (c.has("potential")) s.potential = c.path("potential");  // relative to the case file
  number(c, "cutoff", s.cutoff, Range::non_negative(), units::length);
  s.lmp = c.string_or("lmp", s.lmp);
  s.ranks = static_cast<int>(c.integer_or("ranks", s.ranks, Range::closed(1, 1024)));
  s.use_cache = c.boolean_or("cache", true);
  if (const std::string dir = c.string_or("cache_dir", ""); !dir.empty()) s.cache_dir = expand_home(dir);
  if (c.has("quench")) {
    const Config q = c.section("quench");
    if (material != Material::SiO2) throw c.error("quench", "a melt-quench applies to SiO2 only", "md.material = \"SiO2\"");
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
  }
  if (c.has("cutoff") && material == Material::Si)
    throw c.error("cutoff", "the Stillinger-Weber cutoff (a·sigma) comes from the potential file",
                  "a cutoff for SiO2 (Vashishta) only");
  // Consistency between keys (window inside the strain range, walls vs box, …).
  try {
    validate(s);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: [md]: {}", c.source(), e.what()));
  }
  return s;
}

}  // namespace wearscale::coupling
