#pragma once
// The sides of a surface as a case key: one length L (a square, or Ly from
// square pixels), "Lx,Ly" (what the --size flag gives) or [Lx, Ly]; each in
// metres (1e-4) or with a unit ("100 um").
#include <string>

#include "wearscale/io/config.hpp"
#include "wearscale/io/topography_io.hpp"

namespace wearscale::studies {

/// The sides given by `key` of `c` (both empty when the key is absent);
/// InputError naming the key and value for anything but positive lengths.
bem::TopographySize read_sides(const Config& c, const std::string& key);

}  // namespace wearscale::studies
