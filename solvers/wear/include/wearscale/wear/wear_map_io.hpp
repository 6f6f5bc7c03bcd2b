#pragma once
// Wear maps on disk, each file written atomically:
//   HDF5: /axes/<x>, /axes/<y> (sample points), /region (nx × ny codes, with
//         attributes naming each code), /ratio/<layer> (nx × ny), attributes
//         kind, title and the map's parameters on "/";
//   CSV:  one row per point: x, y, region, layers…, with the legend in comments.
#include <filesystem>

#include "wearscale/wear/wear_map.hpp"

namespace wearscale::wear {

void write_wear_map_h5(const std::filesystem::path& path, const WearMap& map);
void write_wear_map_csv(const std::filesystem::path& path, const WearMap& map);

}  // namespace wearscale::wear
