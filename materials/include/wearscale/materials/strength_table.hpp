#pragma once
// A table of molecular shear strengths against confining pressure: the
// maximum (peak) and dynamic (sliding) shear strength σ_max(p), σ_dyn(p)
// (§9.3.1, Fig. 9.17–9.18), with the provenance of its numbers.
//
// File format (CSV, UTF-8):
//   # key: value                 provenance lines (source, material, units,
//   # key: value                 LAMMPS version, potential, size, seeds, …)
//   pressure_GPa,sigma_max_GPa,sigma_dyn_GPa
//   0,10.6,1.5
//   ...
// Pressures strictly increasing and ≥ 0, strengths ≥ 0, all finite. An HDF5
// file holds the same columns under /strength/{pressure,sigma_max,sigma_dyn}
// in Pa, and each provenance line as a string attribute of /strength.
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "wearscale/core/hdf5_file.hpp"

namespace wearscale::materials {

struct StrengthTable {
  std::string material;            ///< "Si", "SiO2", …
  std::vector<double> pressure;    ///< confining pressure p [Pa]
  std::vector<double> sigma_max;   ///< maximum shear strength [Pa]
  std::vector<double> sigma_dyn;   ///< dynamic (sliding) shear strength [Pa]
  /// Provenance, in file order: {"source", "..."}, {"lammps_version", "..."}, …
  std::vector<std::pair<std::string, std::string>> provenance;
  std::string origin;              ///< the file it was read from (for messages)

  /// The value of a provenance key, or "" if absent.
  std::string info(const std::string& key) const;
};

/// Reads a .csv/.txt or .h5 table. InputError naming the file and line for a
/// missing column, non-monotone pressure, NaN, or a negative strength.
StrengthTable read_strength_table(const std::filesystem::path& file);
/// The CSV format above from its text; `origin` names it in messages.
StrengthTable parse_strength_table_csv(std::string_view text, const std::string& origin);
/// The same from an open HDF5 file (/strength/{pressure,sigma_max,sigma_dyn},
/// each with a pressure "unit" attribute; provenance attributes optional).
StrengthTable parse_strength_table_h5(const H5Reader& file);

/// Writes the table (CSV or HDF5 by extension), atomically. The `material`
/// is stored as the provenance key "material".
void write_strength_table(const std::filesystem::path& file, const StrengthTable& table);

/// Checks the invariants above; InputError naming `table.origin`.
void validate(const StrengthTable& table);

}  // namespace wearscale::materials
