#pragma once
// Small CSV tables for headline curves (written atomically, full precision).
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace wearscale {

/// Writes columns of equal length under one header row, nothing else (so
/// `pandas.read_csv(path)` reads it as is), and beside it `<path>.json` with
/// the column names, the row count, `comments` as its "notes" (source, units,
/// provenance) and the wearscale version.
void write_csv(const std::filesystem::path& path, const std::vector<std::string>& names,
               const std::vector<std::span<const double>>& columns, const std::vector<std::string>& comments = {});
/// The same with a first column of text (`labels`, e.g. the swept values
/// "explicit", "adaptive"), quoted as RFC 4180 asks where needed.
void write_csv(const std::filesystem::path& path, const std::string& label_name, const std::vector<std::string>& labels,
               const std::vector<std::string>& names, const std::vector<std::span<const double>>& columns,
               const std::vector<std::string>& comments = {});

/// The sidecar of a CSV table: "<path>.json".
std::filesystem::path csv_sidecar(const std::filesystem::path& csv);

}  // namespace wearscale
