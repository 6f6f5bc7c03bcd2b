#pragma once
// Small CSV tables for headline curves (written atomically, full precision).
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace wearscale {

/// Writes columns of equal length with a header row; `comments` become
/// leading "# ..." lines (source, units, provenance).
void write_csv(const std::filesystem::path& path, const std::vector<std::string>& names,
               const std::vector<std::span<const double>>& columns, const std::vector<std::string>& comments = {});
/// The same with a first column of text (`labels`, e.g. the swept values
/// "explicit", "adaptive"), quoted as RFC 4180 asks where needed.
void write_csv(const std::filesystem::path& path, const std::string& label_name, const std::vector<std::string>& labels,
               const std::vector<std::string>& names, const std::vector<std::span<const double>>& columns,
               const std::vector<std::string>& comments = {});

}  // namespace wearscale
