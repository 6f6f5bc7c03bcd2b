#include "wearscale/materials/shipped_data.hpp"

#include <cstdlib>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::materials {

std::filesystem::path data_directory() {
  if (const char* dir = std::getenv("WEARSCALE_DATA_DIR"); dir != nullptr && *dir != '\0') return dir;
  return WEARSCALE_MATERIALS_DATA_DIR;
}

std::vector<std::string> shipped_sets() { return {"thesis", "lammps"}; }

std::filesystem::path shipped_table_path(const std::string& set, const std::string& material) {
  std::string file;
  if (set == "thesis") file = "thesis_fig9.18_" + material + ".csv";
  if (set == "lammps") file = "lammps_smoke_" + material + ".csv";
  if (file.empty())
    throw InputError(fmt::format("unknown shipped strength data '{}'; known: {}", set, fmt::join(shipped_sets(), ", ")));
  return data_directory() / file;
}

StrengthTable shipped_table(const std::string& set, const std::string& material) {
  const auto path = shipped_table_path(set, material);
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw InputError(fmt::format("no shipped '{}' strength table for material '{}' ({} does not exist); shipped "
                                 "tables exist for Si and SiO2",
                                 set, material, path.string()));
  return read_strength_table(path);
}

}  // namespace wearscale::materials
