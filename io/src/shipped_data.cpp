#include "wearscale/io/shipped_data.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <mutex>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/io/strength_table_file.hpp"

namespace wearscale::materials {

namespace {

std::mutex override_mutex;
std::filesystem::path override_dir;  // set_data_directory()

const char* environment(const char* name) {
  const char* v = std::getenv(name);
  return v != nullptr && *v != '\0' ? v : nullptr;
}

// share/wearscale/data above the program or module this code is linked into:
// P/bin/wearscale and P/lib/python3.X/dist-packages/wearscale/_wearscale*.so
// both find P/share/wearscale/data, wherever P was installed or moved to.
std::filesystem::path installed_data_directory() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&installed_data_directory), &info) == 0 || info.dli_fname == nullptr) return {};
  std::error_code ec;
  auto dir = std::filesystem::weakly_canonical(std::filesystem::path(info.dli_fname), ec).parent_path();
  if (ec) return {};
  for (int up = 0; up < 6 && !dir.empty(); ++up, dir = dir.parent_path()) {
    const auto candidate = dir / "share" / "wearscale" / "data";
    if (std::filesystem::is_directory(candidate, ec)) return candidate;
    if (dir == dir.root_path()) break;
  }
  return {};
}

}  // namespace

std::filesystem::path installed_file(const std::filesystem::path& relative) {
  static const std::filesystem::path installed = installed_data_directory();
  if (installed.empty() || relative.empty() || relative.is_absolute()) return {};
  const auto candidate = installed.parent_path() / relative;  // share/wearscale/<relative>
  std::error_code ec;
  return std::filesystem::is_regular_file(candidate, ec) ? candidate : std::filesystem::path();
}

void set_data_directory(const std::filesystem::path& dir) {
  const std::lock_guard lock(override_mutex);
  override_dir = dir;
}

std::filesystem::path data_directory() {
  if (const char* dir = environment("WEARSCALE_DATA")) return dir;
  if (const char* dir = environment("WEARSCALE_DATA_DIR")) return dir;  // the name before 0.1 installs
  {
    const std::lock_guard lock(override_mutex);
    if (!override_dir.empty()) return override_dir;
  }
  static const std::filesystem::path installed = installed_data_directory();
  if (!installed.empty()) return installed;
  return WEARSCALE_MATERIALS_DATA_DIR;  // the source tree: a program run from its build tree
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

std::vector<std::string> shipped_materials(const std::string& set) {
  std::string prefix = shipped_table_path(set, "").filename().string();  // "lammps_smoke_.csv"
  prefix.resize(prefix.size() - 4);                                      // "lammps_smoke_"
  std::vector<std::string> out;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(data_directory(), ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() > prefix.size() + 4 && name.rfind(prefix, 0) == 0 && name.ends_with(".csv"))
      out.push_back(name.substr(prefix.size(), name.size() - prefix.size() - 4));
  }
  std::sort(out.begin(), out.end());
  return out;
}

StrengthTable shipped_table(const std::string& set, const std::string& material) {
  const auto path = shipped_table_path(set, material);
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw InputError(fmt::format("no shipped '{}' strength table for material '{}' ({} does not exist; the data "
                                 "folder is $WEARSCALE_DATA, else share/wearscale/data of the installation, else "
                                 "the source tree's materials/data); the '{}' set has tables for {}",
                                 set, material, path.string(), set, fmt::join(shipped_materials(set), ", ")));
  return read_strength_table(path);
}

}  // namespace wearscale::materials
