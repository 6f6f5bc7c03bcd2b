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

}  // namespace wearscale
