#pragma once
// Where wearscale keeps results worth reusing between runs (LAMMPS shear
// tests, DEM junction strengths): one cache root, one subfolder per kind.
//
// Root: $WEARSCALE_CACHE if set, else $XDG_CACHE_HOME/wearscale, else
// ~/.cache/wearscale, else <temp>/wearscale-cache. Kinds: "lammps", "dem".
#include <filesystem>
#include <string>
#include <string_view>

namespace wearscale {

/// The cache root (see above).
std::filesystem::path cache_root();
/// cache_root() / kind.
std::filesystem::path cache_folder(std::string_view kind);
/// "~/x" → "$HOME/x"; other paths unchanged.
std::filesystem::path expand_home(const std::string& path);

}  // namespace wearscale
