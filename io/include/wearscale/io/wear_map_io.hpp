#pragma once
// Wear maps on disk, each file written atomically:
//   HDF5: /axes/<x>, /axes/<y> (sample points), /region (nx × ny codes, with
//         attributes naming each code), /ratio/<layer> (nx × ny), attributes
//         kind, title and the map's parameters on "/" (and the resolved
//         case file as case_toml, when given);
//         with an XDMF sidecar beside it (same name, .xdmf) so ParaView opens
//         the region codes and every layer in the XY plane, x along X;
//   CSV:  one row per point: x, y, region, layers…, with the legend in comments.
#include <filesystem>
#include <string_view>

#include "wearscale/wear/wear_map.hpp"

namespace wearscale::wear {

/// Returns the sidecar's path.
std::filesystem::path write_wear_map_h5(const std::filesystem::path& path, const WearMap& map,
                                        std::string_view case_toml = {});
void write_wear_map_csv(const std::filesystem::path& path, const WearMap& map);

}  // namespace wearscale::wear
