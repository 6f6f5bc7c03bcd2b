#include "wearscale/io/material_definitions.hpp"

#include <algorithm>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/materials/interatomic_model.hpp"

namespace wearscale {

namespace {

std::string joined(const std::vector<std::string>& v) { return fmt::format("{}", fmt::join(v, " | ")); }

}  // namespace

const std::vector<MaterialKey>& material_keys() {
  using namespace units;
  static const std::vector<MaterialKey> keys = {
      {"young", "number", Range::positive(), pressure, "Pa", "", "", "Young's modulus E"},
      {"poisson", "number", Range::open_closed(-1.0, 0.5), dimensionless, "1", "", "", "Poisson's ratio ν"},
      {"density", "number", Range::positive(), density, "kg/m^3", "", "", "density ρ"},
      {"surface_energy", "number", Range::positive(), units::surface_energy, "J/m^2", "", "", "surface energy γ"},
      {"tensile_strength", "number", Range::positive(), pressure, "Pa", "", "", "ideal tensile strength σ_m,N"},
      {"shear_strength", "number", Range::positive(), pressure, "Pa", "", "", "ideal shear strength σ_m,T"},
      {"restitution", "number", Range::open_closed(0.0, 1.0), dimensionless, "1", "", "none",
       "DEM restitution coefficient η (Table 6.5)"},
      {"source", "string", {}, dimensionless, "", "", "defined in <case file>", "where the numbers come from"},
      {"interatomic.pair_style", "choice", {}, dimensionless, "", joined(materials::pair_styles()), "",
       "LAMMPS pair style of the material's potential (MD shear test, §9.3.1)"},
      {"interatomic.potential", "path", {}, dimensionless, "",
       "a file name of letters, digits and . _ + -: in LAMMPS' potentials folder, or a path relative to the case file",
       "", "the potential file (Debian's lammps-data: /usr/share/lammps/potentials, or $LAMMPS_POTENTIALS)"},
      {"interatomic.elements", "list", {}, dimensionless, "",
       "element names (a letter, then letters, digits or _), one per atom type of the structure", "",
       "element of each atom type as the potential file names it (pair_coeff's element map)"},
      {"interatomic.masses", "list", Range::open_closed(0.0, 1000.0), dimensionless, "g/mol", "", "",
       "atomic mass of each element, in g/mol"},
      {"interatomic.structure", "choice", {}, dimensionless, "", joined(materials::structure_names()), "",
       "crystal the sample is cut from, x = [100], y = [010], z = [001] (zincblende, cristobalite: two elements)"},
      {"interatomic.lattice_constant", "number", Range::open_closed(1e-10, 30e-10), length, "m", "", "",
       "edge of the cubic cell of the crystal"},
      {"interatomic.amorphous", "boolean", {}, dimensionless, "", "true | false", "false",
       "melt-quench the crystal into an amorphous solid before the tests (§2.1.3)"},
      {"interatomic.quench_temperatures", "list", Range::positive(), temperature, "K", "", "the protocol's",
       "amorphous: hold temperatures of the melt-quench, melt first, final last"},
      {"interatomic.quench_constant_volume", "boolean", {}, dimensionless, "", "true | false", "false",
       "amorphous: quench at the crystal's volume (a density set by lattice_constant) instead of at zero pressure"},
      {"interatomic.cutoff", "number", Range::closed(0.0, 30e-10), length, "m", "", "0 (the file's)",
       "pair_style vashishta: two-body cutoff r_c written into every entry of the file"},
      {"interatomic.reference_young", "number", Range::positive(), pressure, "Pa", "", "required when amorphous",
       "published Young's modulus of the potential's amorphous solid (the elastic check's reference)"},
      {"interatomic.reference_poisson", "number", Range::open(-1.0, 0.5), dimensionless, "1", "",
       "required when amorphous", "published Poisson's ratio of the potential's amorphous solid"},
      {"interatomic.reference_source", "string", {}, dimensionless, "", "", "required when amorphous",
       "citation of the reference elastic constants"},
      {"interatomic.source", "string", {}, dimensionless, "", "", "", "citation of the potential (provenance)"},
  };
  return keys;
}

namespace {

const MaterialKey& declared(const std::string& key) {
  for (const auto& k : material_keys())
    if (k.key == key) return k;
  throw std::logic_error("material key '" + key + "' is not declared in material_keys()");
}

// A number of `c` read as its declaration `prefix` + `key` says.
double number(const Config& c, const std::string& key, const std::string& prefix = "") {
  const auto& k = declared(prefix + key);
  return c.number(key, k.range, k.dimension);
}

std::vector<double> numbers(const Config& c, const std::string& key, const std::string& prefix = "") {
  const auto& k = declared(prefix + key);
  return c.numbers(key, k.range, k.dimension);
}

constexpr const char* kInteratomic = "interatomic.";

materials::InteratomicModel read_interatomic(const Config& c, const std::string& name) {
  materials::InteratomicModel m;
  const auto& styles = materials::pair_styles();
  m.pair_style = c.string("pair_style");
  if (std::find(styles.begin(), styles.end(), m.pair_style) == styles.end())
    throw c.error("pair_style", "not a supported pair style", declared("interatomic.pair_style").allowed);
  m.potential = potential_file(c, "potential");
  if (!materials::safe_file_name(m.potential.filename().string()))
    throw c.error("potential", "the file name has characters a LAMMPS deck would read as syntax",
                  declared("interatomic.potential").allowed);
  m.elements = c.values_as_text("elements");
  for (const auto& e : m.elements)
    if (!materials::safe_element_name(e))
      throw c.error("elements", fmt::format("'{}' is not an element name", e), declared("interatomic.elements").allowed);
  m.masses = numbers(c, "masses", kInteratomic);
  const std::string structure = c.string("structure");
  try {
    m.structure = materials::structure_from_string(structure);
  } catch (const InputError&) {
    throw c.error("structure", "unknown crystal structure", declared("interatomic.structure").allowed);
  }
  m.lattice_constant = number(c, "lattice_constant", kInteratomic);
  m.amorphous = c.boolean_or("amorphous", false);
  c.mark_used("quench_temperatures");
  if (c.has("quench_temperatures")) m.quench_temperatures = numbers(c, "quench_temperatures", kInteratomic);
  m.quench_constant_volume = c.boolean_or("quench_constant_volume", false);
  if (c.has("cutoff")) m.cutoff = number(c, "cutoff", kInteratomic);
  if (c.has("reference_young") || c.has("reference_poisson") || c.has("reference_source")) {
    m.reference.young = number(c, "reference_young", kInteratomic);
    m.reference.poisson = number(c, "reference_poisson", kInteratomic);
    m.reference.source = c.string("reference_source");
  }
  m.source = c.string_or("source", "");
  try {
    materials::validate(m, name);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: [materials.define.{}.interatomic]: {}", c.source(), name, e.what()));
  }
  return m;
}

}  // namespace

std::filesystem::path potential_file(const Config& c, std::string_view key) {
  const std::string raw = c.string(key);
  if (raw.find('/') != std::string::npos) return c.path(key);
  std::error_code ec;
  const auto beside = c.path(key);
  if (std::filesystem::is_regular_file(beside, ec)) return beside;
  return raw;
}

void define_materials_from(materials::MaterialLibrary& library, const Config& root) {
  const Config defs = root.section("materials.define");
  for (const auto& name : root.keys("materials.define")) {
    const Config c = defs.section(name);
    materials::Material m;
    m.name = name;
    m.young = number(c, "young");
    m.poisson = number(c, "poisson");
    m.density = number(c, "density");
    m.surface_energy = number(c, "surface_energy");
    m.tensile_strength = number(c, "tensile_strength");
    m.shear_strength = number(c, "shear_strength");
    if (c.has("restitution")) m.restitution = number(c, "restitution");
    m.source = c.string_or("source", "defined in " + root.source());
    if (c.has("interatomic")) m.interatomic = read_interatomic(c.section("interatomic"), name);
    library.add(std::move(m));
  }
}

}  // namespace wearscale
