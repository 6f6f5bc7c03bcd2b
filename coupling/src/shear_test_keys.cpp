#include "wearscale/coupling/shear_test_keys.hpp"

#include <cmath>
#include <cstdlib>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/cache_folder.hpp"
#include "wearscale/io/key_table.hpp"
#include "wearscale/io/material_definitions.hpp"
#include "wearscale/md/result_cache.hpp"

namespace wearscale::coupling {

using namespace md;

namespace {

// What the keys of the shear test fill: the material and its interatomic
// model (which the keys may override), the preset the protocol starts from,
// and the protocol itself, each key defaulting to the preset's value.
struct ShearTestKeys {
  std::string material;
  materials::InteratomicModel model;
  std::string preset = "smoke";
  ShearTestSpec spec;
  std::vector<double> window;  ///< [begin, end], when given
  std::string cache_dir;       ///< "": the user cache folder's lammps/
};
using K = ShearTestKeys;

const char* const kFromPreset = "from the preset";
const char* const kMaterials = "Si | SiO2 | a [materials.define.<name>] with an interatomic table";

// [md] material: the material of the study.
const KeyTable<K>& material_key() {
  static const auto table = KeyTable<K>()
                                .string("material", &K::material, "material of the shear test")
                                .required()
                                .allowed(kMaterials);
  return table;
}

// The model's keys a case may override (the [md] keys of the SiO2 and Si tests).
const KeyTable<K>& model_keys() {
  static const auto table =
      KeyTable<K>()
          .custom("potential", "path", "", "",
                  "interatomic potential file (a name in LAMMPS' potentials folder, or relative to the case file)",
                  [](const Config& c, const std::string& key, K& k) {
                    if (c.has(key)) k.model.potential = potential_file(c, key);
                  })
          .fallback("the material's")
          .number("lattice_constant", [](K& k) -> double& { return k.model.lattice_constant; }, Range::positive(),
                  units::length, "lattice constant of the sample")
          .fallback("the material's")
          .number("cutoff", [](K& k) -> double& { return k.model.cutoff; }, Range::non_negative(), units::length,
                  "two-body cutoff r_c (pair_style vashishta only)")
          .fallback("the material's")
          .then([](const Config& c, K& k) {
            if (c.has("cutoff") && k.model.pair_style != "vashishta")
              throw c.error("cutoff", fmt::format("{} takes its cutoff from the potential file (pair_style {})",
                                                  k.material, k.model.pair_style),
                            "a cutoff for pair_style vashishta only");
          });
  return table;
}

const KeyTable<K>& preset_key() {
  static const auto table = KeyTable<K>().choice(
      "preset", &K::preset, std::vector<std::string>{"smoke", "thesis"},
      "smoke (small boxes, 100 m/s: seconds to a minute per pressure) or thesis (10 nm boxes, 10 m/s: hours per "
      "pressure); the keys below override it");
  return table;
}

// A key of the protocol, defaulting to the preset's value.
template <class T>
auto protocol(T ShearTestSpec::*member) {
  return [member](K& k) -> T& { return k.spec.*member; };
}
template <class T>
auto quench(T QuenchSchedule::*member) {
  return [member](K& k) -> T& { return k.spec.quench.*member; };
}

// [quench]: the melt-quench of an amorphous sample.
const KeyTable<K>& quench_keys() {
  const units::Dimension rate = units::temperature / units::time;
  static const auto table =
      KeyTable<K>()
          .numbers("temperatures", quench(&QuenchSchedule::temperatures), Range::positive(), units::temperature,
                   "melt-quench (amorphous samples): temperature schedule")
          .fallback("the material's, else the thesis' SiO2 schedule")
          .number("hold_time", quench(&QuenchSchedule::hold_time), Range::positive(), units::time,
                  "melt-quench: time held at each temperature")
          .fallback(kFromPreset)
          .number("cooling_rate", quench(&QuenchSchedule::cooling_rate), Range::positive(), rate,
                  "melt-quench: cooling rate")
          .unit("K/s")
          .fallback(kFromPreset)
          .number("final_cooling_rate", quench(&QuenchSchedule::final_cooling_rate), Range::positive(), rate,
                  "melt-quench: last cooling rate")
          .unit("K/s")
          .fallback(kFromPreset)
          .number("timestep", quench(&QuenchSchedule::timestep), Range::open_closed(0.0, 1e-14), units::time,
                  "melt-quench: time step")
          .fallback(kFromPreset)
          .number("pressure", quench(&QuenchSchedule::pressure), Range::any(), units::pressure,
                  "melt-quench: barostat pressure")
          .fallback(kFromPreset)
          .number("barostat_damp", quench(&QuenchSchedule::barostat_damp), Range::positive(), units::time,
                  "melt-quench: barostat damping time")
          .fallback(kFromPreset)
          .number("bulk_modulus", quench(&QuenchSchedule::bulk_modulus), Range::positive(), units::pressure,
                  "melt-quench: bulk modulus of the barostat")
          .fallback(kFromPreset)
          .number("thermostat_damp", quench(&QuenchSchedule::thermostat_damp), Range::positive(), units::time,
                  "melt-quench: thermostat damping time")
          .fallback(kFromPreset)
          .boolean("constant_volume", quench(&QuenchSchedule::constant_volume),
                   "melt-quench at the crystal's volume, no barostat")
          .fallback("the material's");
  return table;
}

void read_quench(const Config& c, K& k) {
  if (!k.model.amorphous)
    throw c.error("quench", fmt::format("a melt-quench applies to an amorphous sample; {} is a crystal", k.material),
                  "an amorphous material (SiO2, or interatomic.amorphous = true)");
  quench_keys().read(c.section("quench"), k);
}

// The protocol keys present in a table override the spec (each key's default
// is its current value: every key is "read", so a misspelt one gets a "did
// you mean" suggestion).
const KeyTable<K>& protocol_keys() {
  static const auto table =
      KeyTable<K>()
          .numbers("pressures", protocol(&ShearTestSpec::pressures), Range::non_negative(), units::pressure,
                   "normal pressures of the points, one run each")
          .allowed("≥ 0, increasing")
          .fallback("")
          .number("lateral_size", protocol(&ShearTestSpec::lateral_size), Range::positive(), units::length,
                  "box side x = y, rounded to whole lattice cells")
          .fallback(kFromPreset)
          .number("height", protocol(&ShearTestSpec::height), Range::positive(), units::length, "box height")
          .fallback(kFromPreset)
          .number("wall_thickness", protocol(&ShearTestSpec::wall_thickness), Range::positive(), units::length,
                  "thickness of the rigid walls")
          .fallback(kFromPreset)
          .number("thermostat_thickness", protocol(&ShearTestSpec::thermostat_thickness), Range::positive(),
                  units::length, "thickness of the thermostatted layers")
          .fallback(kFromPreset)
          .number("shear_velocity", protocol(&ShearTestSpec::shear_velocity), Range::positive(), units::velocity,
                  "imposed shear velocity")
          .fallback(kFromPreset)
          .number("temperature", protocol(&ShearTestSpec::temperature), Range::positive(), units::temperature,
                  "thermostat temperature")
          .fallback(kFromPreset)
          .number("langevin_damp", protocol(&ShearTestSpec::langevin_damp), Range::positive(), units::time,
                  "Langevin damping time")
          .fallback(kFromPreset)
          .number("timestep", protocol(&ShearTestSpec::timestep), Range::open_closed(0.0, 1e-14), units::time,
                  "time step")
          .fallback(kFromPreset)
          .number("compression_time", protocol(&ShearTestSpec::compression_time), Range::non_negative(), units::time,
                  "time under load before shearing")
          .fallback(kFromPreset)
          .number("strain_end", protocol(&ShearTestSpec::strain_end), Range::open_closed(0.0, 10.0),
                  units::dimensionless, "shear strain at the end of the run")
          .fallback(kFromPreset)
          .numbers("window", &K::window, Range::closed(0.0, 10.0), units::dimensionless,
                   "strain range [begin, end] over which σ_dyn is the mean shear stress")
          .fallback(kFromPreset)
          .then([](const Config& c, K& k) {
            if (!c.has("window")) return;
            if (k.window.size() != 2)
              throw c.error("window", fmt::format("{} values", k.window.size()), "[begin, end] strains");
            k.spec.window_begin = k.window[0];
            k.spec.window_end = k.window[1];
          })
          .integer("sample_steps", protocol(&ShearTestSpec::sample_steps), Range::closed(1, 1e7),
                   "steps between thermo samples")
          .fallback(kFromPreset)
          .integer("seed", protocol(&ShearTestSpec::seed), Range::closed(1, 9e8), "random seed of the velocities")
          .fallback(kFromPreset)
          .number("modulus_strain", protocol(&ShearTestSpec::modulus_strain), Range::open(0.0, 1.0),
                  units::dimensionless, "the elastic shear modulus is the slope of the shear curve over strains up to this")
          .string("lmp", protocol(&ShearTestSpec::lmp), "LAMMPS executable")
          .fallback("lmp on PATH")
          .integer("ranks", protocol(&ShearTestSpec::ranks), Range::closed(1, 1024),
                   "MPI ranks of each LAMMPS run, through mpirun when > 1 (per point: under `mpirun -np N wearscale` "
                   "the points are spread over the N ranks, each point's lmp on this many ranks of its own)")
          .boolean("cache", protocol(&ShearTestSpec::use_cache), "read identical runs from the result cache")
          .string("cache_dir", &K::cache_dir, "result cache folder")
          .fallback("$WEARSCALE_CACHE/lammps, else ~/.cache/wearscale/lammps")
          .then([](const Config&, K& k) {
            if (!k.cache_dir.empty()) k.spec.cache_dir = expand_home(k.cache_dir);
          })
          .table("quench", "the melt-quench of an amorphous sample (its keys below)", read_quench)
          .read_if([](const Config& c, const K&) { return c.has("quench"); });
  return table;
}

void append(Schema& out, Schema rows) {
  for (auto& row : rows) out.push_back(std::move(row));
}

}  // namespace

Schema shear_test_schema(const std::string& prefix) {
  const auto name = [&](const std::string& key) { return prefix.empty() ? key : prefix + "." + key; };
  Schema out;
  append(out, preset_key().schema(prefix));
  append(out, protocol_keys().schema(prefix));
  append(out, model_keys().schema(prefix));
  append(out, quench_keys().schema(name("quench")));
  out.push_back({name("<material>"), "table", "a material of the case", "", "",
                 "keys for that material alone, overriding those above (a pipeline with several materials)", ""});
  return out;
}

Schema md_schema() {
  Schema out = material_key().schema("md");
  append(out, shear_test_schema("md"));
  return out;
}

ShearTestSpec read_shear_test_spec(const Config& root) {
  const Config c = root.section("md");
  materials::MaterialLibrary library;
  define_materials_from(library, root);
  K k;
  material_key().read(c, k);
  const std::string& material = k.material;
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

ShearTestSpec read_shear_test_spec(const Config& c, const std::string& material,
                                   const materials::InteratomicModel& declared) {
  // A table named after the material holds keys for it alone ([scale.molecular.Cu] strain_end = 0.5).
  const bool own = c.has(material) && !c.section(material).keys().empty();
  const Config mine = c.section(material);
  K k;
  k.material = material;
  k.model = declared;
  model_keys().read(c, k);
  if (own) model_keys().read(mine, k);
  preset_key().read(c, k);
  try {
    k.spec = preset_spec(material, k.model, k.preset);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: [md]: {}", c.source(), e.what()));
  }
  k.spec.pressures.clear();
  protocol_keys().read(c, k);
  if (own) protocol_keys().read(mine, k);
  ShearTestSpec s = std::move(k.spec);
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
