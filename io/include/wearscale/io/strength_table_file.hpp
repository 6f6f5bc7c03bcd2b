#pragma once
// Strength tables (materials/strength_table.hpp) in files: CSV in the
// project's convention (one header line pressure_Pa,sigma_max_Pa,sigma_dyn_Pa,
// the provenance in the sidecar <table>.csv.json), or HDF5
// (/strength/{pressure,sigma_max,sigma_dyn}). The reader also takes the
// older CSV form: leading "# key: value" provenance lines and columns in GPa
// (pressure_GPa, ...), as hand-written tables and wearscale before the SI
// convention wrote them.
#include <filesystem>
#include <string>
#include <string_view>

#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/materials/strength_table.hpp"

namespace wearscale::materials {

/// Reads a .csv/.txt or .h5 table. InputError naming the file and line for a
/// missing column, non-monotone pressure, NaN, or a negative strength.
StrengthTable read_strength_table(const std::filesystem::path& file);
/// The CSV format (materials/strength_table.hpp) from its text; `origin` names it in messages.
StrengthTable parse_strength_table_csv(std::string_view text, const std::string& origin);
/// The same from an open HDF5 file (/strength/{pressure,sigma_max,sigma_dyn},
/// each with a pressure "unit" attribute; provenance attributes optional).
StrengthTable parse_strength_table_h5(const H5Reader& file);

/// Writes the table (CSV or HDF5 by extension), atomically. The `material`
/// is stored as the provenance key "material".
void write_strength_table(const std::filesystem::path& file, const StrengthTable& table);

}  // namespace wearscale::materials
