#include "wearscale/dem/periodic_images.hpp"

#include <cmath>
#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::dem {

PeriodicImages PeriodicImages::within(const Box& box, double cut) {
  PeriodicImages out;
  const Vec3 l = box.length();
  for (std::size_t a = 0; a < 3; ++a) {
    if (!box.periodic[a]) {
      out.reach[a] = 0;
      continue;
    }
    // Wrapped positions differ by less than L: |d + s L| < cut needs |s| < cut/L + 1.
    out.reach[a] = std::max(1, static_cast<int>(std::ceil(cut / l[static_cast<int>(a)])));
  }
  if (static_cast<double>(2 * out.reach[0] + 1) * (2 * out.reach[1] + 1) * (2 * out.reach[2] + 1) > max_count)
    throw InputError(fmt::format(
        "DEM box: periodic lengths {:.6g} × {:.6g} × {:.6g} against the neighbour cutoff 2 r_max + reach + skin = "
        "{:.6g} put more than {} periodic images of a particle within reach; allowed: at most two axes shorter than "
        "the cutoff, or lengths ≥ {:.6g} (half the cutoff)",
        l.x, l.y, l.z, cut, max_count, 0.5 * cut));
  return out;
}

std::array<int, 3> PeriodicImages::shift(std::uint8_t s) const {
  int k = s;
  std::array<int, 3> out{};
  for (std::size_t a = 0; a < 3; ++a) {
    out[a] = k % width(a) - reach[a];
    k /= width(a);
  }
  return out;
}

int PeriodicImages::find(const std::array<int, 3>& s) const {
  for (std::size_t a = 0; a < 3; ++a)
    if (s[a] < -reach[a] || s[a] > reach[a]) return -1;
  return index(s[0], s[1], s[2]);
}

void PeriodicImages::vectors(const Box& box, Vec3* out) const {
  const Vec3 l = box.length();
  for (int sz = -reach[2]; sz <= reach[2]; ++sz)
    for (int sy = -reach[1]; sy <= reach[1]; ++sy)
      for (int sx = -reach[0]; sx <= reach[0]; ++sx) out[index(sx, sy, sz)] = {sx * l.x, sy * l.y, sz * l.z};
}

}  // namespace wearscale::dem
