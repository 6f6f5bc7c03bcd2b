#pragma once
// The strength tables wearscale ships in materials/data/.
#include <filesystem>
#include <string>
#include <vector>

#include "wearscale/materials/strength_table.hpp"

namespace wearscale::materials {

/// The folder of shipped data: $WEARSCALE_DATA_DIR if set, else the source
/// tree's materials/data.
std::filesystem::path data_directory();

/// Shipped tables by name: "thesis" (Fig. 9.18 laws) or "lammps" (computed
/// by wearscale's LAMMPS backend, smoke preset), for "Si" or "SiO2".
/// InputError listing what exists if there is no such table.
StrengthTable shipped_table(const std::string& set, const std::string& material);
std::filesystem::path shipped_table_path(const std::string& set, const std::string& material);
std::vector<std::string> shipped_sets();

}  // namespace wearscale::materials
