#pragma once
// The strength tables wearscale ships in materials/data/.
#include <filesystem>
#include <string>
#include <vector>

#include "wearscale/materials/strength_table.hpp"

namespace wearscale::materials {

/// The folder of shipped data, the first of: $WEARSCALE_DATA, $WEARSCALE_DATA_DIR
/// (the older name), set_data_directory(), share/wearscale/data above the
/// installed program or Python module (cmake --install), the source tree's
/// materials/data (a program run from its build tree).
std::filesystem::path data_directory();
/// A file that `cmake --install` put under share/wearscale of the installation
/// holding the program or module (the example cases: "cases/hertz_pin.toml"),
/// so that the examples of the help and man page run from an installed tree;
/// empty when there is no such installed file.
std::filesystem::path installed_file(const std::filesystem::path& relative);
/// Makes data_directory() return `dir` (unless an environment variable is set);
/// empty: back to the search above.
void set_data_directory(const std::filesystem::path& dir);

/// Shipped tables by name: "thesis" (Fig. 9.18 laws, Si and SiO2) or "lammps"
/// (computed by wearscale's LAMMPS backend: Si, SiO2 and the demonstration
/// materials). InputError listing what exists if there is no such table.
StrengthTable shipped_table(const std::string& set, const std::string& material);
std::filesystem::path shipped_table_path(const std::string& set, const std::string& material);
std::vector<std::string> shipped_sets();
/// The materials a set has a table for, from the data folder's file names.
std::vector<std::string> shipped_materials(const std::string& set);

}  // namespace wearscale::materials
