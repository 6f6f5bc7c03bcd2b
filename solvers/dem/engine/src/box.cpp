#include "wearscale/dem/box.hpp"

#include <cmath>

namespace wearscale::dem {

int Box::wrap(int axis, double& coordinate) const {
  if (!periodic[static_cast<std::size_t>(axis)]) return 0;
  const double l = hi[axis] - lo[axis];
  double shifts = std::floor((coordinate - lo[axis]) / l);
  if (shifts == 0.0) return 0;
  coordinate -= shifts * l;
  if (coordinate >= hi[axis]) {  // rounding at the upper edge: one period more
    coordinate = lo[axis];
    shifts += 1.0;
  }
  return -static_cast<int>(shifts);
}

Vec3 Box::minimum_image(Vec3 d) const {
  for (int a = 0; a < 3; ++a) {
    if (!periodic[static_cast<std::size_t>(a)]) continue;
    const double l = hi[a] - lo[a];
    d[a] -= l * std::nearbyint(d[a] / l);
  }
  return d;
}

}  // namespace wearscale::dem
