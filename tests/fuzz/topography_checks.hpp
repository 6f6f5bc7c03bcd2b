#pragma once
// What the topography harnesses assert about what they read: a grid of
// positive, finite size holding finite heights. A violation aborts.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "wearscale/core/field.hpp"
#include "wearscale/io/topography_io.hpp"

namespace fuzz {

/// The first input byte says whether the caller gives the size (as
/// `contact --set contact.size=…` does); the reader sees the rest.
inline wearscale::bem::TopographySize given_size(const std::uint8_t* data) {
  wearscale::bem::TopographySize given;
  if (data[0] & 1) given.lx = given.ly = 1e-3;
  return given;
}

/// A topography: a grid of positive, finite size holding finite heights.
inline void check_topography(const wearscale::RealField& h) {
  const wearscale::Grid2D& g = h.grid();
  if (g.nx == 0 || g.ny == 0 || h.size() != g.nx * g.ny || !(g.lx > 0.0) || !(g.ly > 0.0) || !std::isfinite(g.lx) ||
      !std::isfinite(g.ly))
    std::abort();
  for (double v : h)
    if (!std::isfinite(v)) std::abort();
}

}  // namespace fuzz
