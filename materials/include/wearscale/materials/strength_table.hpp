#pragma once
// A table of molecular shear strengths against confining pressure: the
// maximum (peak) and dynamic (sliding) shear strength σ_max(p), σ_dyn(p)
// (§9.3.1, Fig. 9.17–9.18), with the provenance of its numbers.
//
// Read and written by io/strength_table_file.hpp. File format (CSV, UTF-8):
//   pressure_Pa,sigma_max_Pa,sigma_dyn_Pa
//   0,1.06e+10,1.5e+09
//   ...
// with the provenance (source, material, LAMMPS version, potential and its
// SHA-256, size, seeds, …) as "key: value" notes in <table>.csv.json; the
// reader also takes "# key: value" lines before the header and columns in
// kPa, MPa or GPa (pressure_GPa, …: the older form).
// Pressures increasing (a pressure listed twice is a jump) and ≥ 0,
// strengths ≥ 0, all finite. An HDF5
// file holds the same columns under /strength/{pressure,sigma_max,sigma_dyn}
// in Pa, and each provenance line as a string attribute of /strength.
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <functional>

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

/// Checks the invariants above; InputError naming `table.origin`.
void validate(const StrengthTable& table);
/// The same, `where_row(r)` naming row r in messages ("file:line" when read).
void validate(const StrengthTable& table, const std::function<std::string(std::size_t)>& where_row);

}  // namespace wearscale::materials
