#pragma once
// Small CSV tables for headline curves (written atomically, full precision).
// Every column carries its SI unit in its header name, one convention for
// every table (docs/running.md, Outputs): `<name>_<unit>` with the unit
// spelt as a word, "p_N_Pa", "q_rad_per_m", "pin_wear_m3", "C_m4"; a
// dimensionless column (unit "1") is its plain name, "friction".
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace wearscale {

/// The header name of a column `name` in `unit` (SI: "Pa", "m^3", "rad/m",
/// "J/m^2", "kg·m^-1", "mm^3/(N·m)"; "1" for a dimensionless one): "p_N" in "Pa" → "p_N_Pa",
/// "q" in "rad/m" → "q_rad_per_m", "k" in "mm^3/(N·m)" → "k_mm3_per_N_per_m",
/// "friction" in "1" → "friction".
/// std::invalid_argument for an empty unit or one it cannot spell.
std::string csv_column_name(const std::string& name, const std::string& unit);

/// Writes columns of equal length under one header row, nothing else (so
/// `pandas.read_csv(path)` reads it as is, every numeric column as float64:
/// each number is written as pandas writes a float, "0.0", "3126.0",
/// "1.5e-06", "nan", "inf", never "-0"), and beside it `<path>.json` with
/// the column names, their units, the row count, `notes` (source, method,
/// provenance) and the wearscale version. `units` is one per column, as
/// H5Writer::write_table takes them: a column cannot be written without one.
void write_csv(const std::filesystem::path& path, const std::vector<std::string>& names,
               const std::vector<std::span<const double>>& columns, const std::vector<std::string>& units,
               const std::vector<std::string>& notes = {});
/// The same with a first column of text (`labels`, e.g. the swept values
/// "explicit", "adaptive"; no unit), quoted as RFC 4180 asks where needed.
void write_csv(const std::filesystem::path& path, const std::string& label_name, const std::vector<std::string>& labels,
               const std::vector<std::string>& names, const std::vector<std::span<const double>>& columns,
               const std::vector<std::string>& units, const std::vector<std::string>& notes = {});

/// The sidecar of a CSV table: "<path>.json".
std::filesystem::path csv_sidecar(const std::filesystem::path& csv);

}  // namespace wearscale
