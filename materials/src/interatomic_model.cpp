#include "wearscale/materials/interatomic_model.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::materials {

namespace {

struct StructureInfo {
  Structure structure;
  const char* name;
  int types;
  int atoms_per_cell;
};
constexpr StructureInfo kStructures[] = {
    {Structure::Fcc, "fcc", 1, 4},
    {Structure::Bcc, "bcc", 1, 2},
    {Structure::SimpleCubic, "sc", 1, 1},
    {Structure::Diamond, "diamond", 1, 8},
    {Structure::Zincblende, "zincblende", 2, 8},
    {Structure::Cristobalite, "cristobalite", 2, 24},
};

const StructureInfo& info(Structure s) {
  for (const auto& i : kStructures)
    if (i.structure == s) return i;
  return kStructures[0];
}

bool is_alpha(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_alnum(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; }

}  // namespace

std::string to_string(Structure s) { return info(s).name; }

std::vector<std::string> structure_names() {
  std::vector<std::string> out;
  for (const auto& i : kStructures) out.emplace_back(i.name);
  return out;
}

Structure structure_from_string(const std::string& name) {
  for (const auto& i : kStructures)
    if (name == i.name) return i.structure;
  throw InputError(fmt::format("crystal structure '{}' is unknown; allowed: {}", name, fmt::join(structure_names(), ", ")));
}

int structure_types(Structure s) { return info(s).types; }
int structure_atoms_per_cell(Structure s) { return info(s).atoms_per_cell; }

const std::vector<std::string>& pair_styles() {
  // One potential file and the element map; no other argument. (meam needs
  // two files, airebo a cutoff argument, snap two files: not here.)
  static const std::vector<std::string> styles = {"eam",    "eam/alloy",  "eam/fs",        "adp",         "sw",
                                                  "tersoff", "tersoff/mod", "tersoff/mod/c", "tersoff/zbl", "vashishta",
                                                  "meam/spline", "edip",    "extep",         "lcbop",       "rebo"};
  return styles;
}

bool safe_element_name(const std::string& name) {
  if (name.empty() || name.size() > 16 || !is_alpha(name[0])) return false;
  return std::all_of(name.begin(), name.end(), [](char c) { return is_alnum(c) || c == '_'; });
}

bool safe_file_name(const std::string& name) {
  if (name.empty() || name.size() > 128 || !is_alnum(name[0])) return false;
  return std::all_of(name.begin(), name.end(),
                     [](char c) { return is_alnum(c) || c == '.' || c == '_' || c == '+' || c == '-'; });
}

void validate(const InteratomicModel& m, const std::string& what) {
  auto bad = [&](const std::string& field, const std::string& problem) {
    throw InputError(fmt::format("interatomic model of {}: {}: {}", what, field, problem));
  };
  const auto& styles = pair_styles();
  if (std::find(styles.begin(), styles.end(), m.pair_style) == styles.end())
    bad("pair_style", fmt::format("'{}' is not supported; allowed: {}", m.pair_style, fmt::join(styles, ", ")));
  const std::string file = m.potential.filename().string();
  if (!safe_file_name(file))
    bad("potential", fmt::format("file name '{}' has characters a LAMMPS deck would read as syntax; allowed: letters, "
                                 "digits and . _ + - (starting with a letter or digit), at most 128",
                                 file));
  const int types = structure_types(m.structure);
  if (static_cast<int>(m.elements.size()) != types)
    bad("elements", fmt::format("{} given; the {} structure has {} atom type{}", m.elements.size(),
                                to_string(m.structure), types, types > 1 ? "s" : ""));
  for (const auto& e : m.elements)
    if (!safe_element_name(e))
      bad("elements", fmt::format("'{}' is not an element name; allowed: a letter then letters, digits or _, at most 16", e));
  if (m.pair_style == "eam" && m.elements.size() != 1)
    bad("pair_style", "eam (funcfl) files hold one element; use eam/alloy or eam/fs for several");
  if (m.masses.size() != m.elements.size())
    bad("masses", fmt::format("{} given for {} element{}", m.masses.size(), m.elements.size(),
                              m.elements.size() > 1 ? "s" : ""));
  for (double x : m.masses)
    if (!(x > 0.0 && x <= 1000.0)) bad("masses", fmt::format("{} g/mol; allowed: (0, 1000]", x));
  if (!(m.lattice_constant > 1e-10 && m.lattice_constant <= 30e-10))
    bad("lattice_constant", fmt::format("{:g} Å; allowed: (1, 30] Å", m.lattice_constant * 1e10));
  if (m.cutoff != 0.0 && m.pair_style != "vashishta")
    bad("cutoff", "a cutoff rewrite applies to pair_style vashishta only (other styles take theirs from the file)");
  if (!(m.cutoff >= 0.0 && m.cutoff <= 30e-10)) bad("cutoff", fmt::format("{:g} Å; allowed: [0, 30] Å", m.cutoff * 1e10));
  if (m.amorphous && !m.reference.given())
    bad("reference", "an amorphous sample has no ideal lattice to compute its elastic constants on: give the published "
                     "Young's modulus and Poisson's ratio of the potential's amorphous solid (reference_young, "
                     "reference_poisson, reference_source)");
  if (!m.amorphous && (!m.quench_temperatures.empty() || m.quench_constant_volume))
    bad("quench", "a melt-quench applies to an amorphous sample only (amorphous = true)");
  for (std::size_t i = 0; i < m.quench_temperatures.size(); ++i)
    if (!(m.quench_temperatures[i] > 0.0) || (i > 0 && !(m.quench_temperatures[i] < m.quench_temperatures[i - 1])))
      bad("quench_temperatures", "positive and decreasing (melt first, final last)");
  if (m.quench_temperatures.size() == 1) bad("quench_temperatures", "at least a melt and a final temperature");
  if (m.reference.given() && !(m.reference.poisson > -1.0 && m.reference.poisson < 0.5))
    bad("reference_poisson", fmt::format("{}; allowed: (-1, 0.5)", m.reference.poisson));
}

InteratomicModel silicon_model() {
  InteratomicModel m;
  m.pair_style = "sw";
  m.potential = "Si.sw";
  m.elements = {"Si"};
  m.masses = {28.0855};
  m.structure = Structure::Diamond;
  m.lattice_constant = 5.431e-10;
  m.source = "Stillinger & Weber 1985, doi:10.1103/PhysRevB.31.5262 (LAMMPS Si.sw)";
  return m;
}

InteratomicModel silica_model() {
  InteratomicModel m;
  m.pair_style = "vashishta";
  m.potential = "SiO.1990.vashishta";
  m.elements = {"Si", "O"};
  m.masses = {28.0855, 15.9994};
  m.structure = Structure::Cristobalite;
  m.lattice_constant = 7.16e-10;  // idealised cubic β-cristobalite
  m.amorphous = true;
  m.cutoff = 8e-10;               // §2.1.3: r_c = 8 Å (Luo et al. 2016)
  m.reference = {120e9, 0.22, "thesis Sec. 2.1.3: the melt-quenched Vashishta SiO2 at 0 K, E = 120 GPa, nu = 0.22"};
  m.source = "Vashishta et al. 1990, doi:10.1103/PhysRevB.41.12197 (LAMMPS SiO.1990.vashishta), r_c = 8 A";
  return m;
}

}  // namespace wearscale::materials
