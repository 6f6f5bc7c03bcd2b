#pragma once
// The simulation box: bounds and which axes are periodic. Non-periodic axes
// are open (particles may leave the nominal bounds; walls confine them).
#include <array>

#include "wearscale/dem/vec3.hpp"

namespace wearscale::dem {

struct Box {
  Vec3 lo{};
  Vec3 hi{};
  std::array<bool, 3> periodic{true, true, true};

  Vec3 length() const { return hi - lo; }
  double volume() const {
    const Vec3 l = length();
    return l.x * l.y * l.z;
  }
  /// Maps a periodic coordinate into [lo, hi); returns the number of box
  /// lengths added (the image shift), 0 on open axes.
  int wrap(int axis, double& coordinate) const;
  /// The shortest periodic image of a separation vector.
  Vec3 minimum_image(Vec3 d) const;
};

}  // namespace wearscale::dem
