#include "wearscale/core/cache_folder.hpp"

#include <cstdlib>

namespace wearscale {

namespace {
const char* variable(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? value : nullptr;
}
}  // namespace

std::filesystem::path expand_home(const std::string& path) {
  if (path == "~" || path.rfind("~/", 0) == 0)
    if (const char* home = variable("HOME")) return std::filesystem::path(home) / path.substr(path.size() > 1 ? 2 : 1);
  return path;
}

std::filesystem::path cache_root() {
  if (const char* env = variable("WEARSCALE_CACHE")) return expand_home(env);
  if (const char* xdg = variable("XDG_CACHE_HOME")) return std::filesystem::path(xdg) / "wearscale";
  if (const char* home = variable("HOME")) return std::filesystem::path(home) / ".cache" / "wearscale";
  return std::filesystem::temp_directory_path() / "wearscale-cache";
}

std::filesystem::path cache_folder(std::string_view kind) { return cache_root() / std::string(kind); }

}  // namespace wearscale
