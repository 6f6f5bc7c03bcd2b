#include "wearscale/dem/cell_order.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace wearscale::dem {

std::vector<std::size_t> cell_order(std::span<const Vec3> x, double cell) {
  if (!(cell > 0.0) || !std::isfinite(cell)) throw std::invalid_argument("cell_order: the cell size must be > 0");
  const std::size_t n = x.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  if (n == 0) return order;
  Vec3 lo = x[0], hi = x[0];
  for (const Vec3& p : x)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  // Cells per axis, bounded so that the flat index fits (a cell far below
  // the box's size merges cells; the order is still along the axes).
  std::uint64_t cells[3];
  for (int a = 0; a < 3; ++a) {
    const double count = std::floor((hi[a] - lo[a]) / cell) + 1.0;
    cells[a] = static_cast<std::uint64_t>(std::clamp(count, 1.0, 1.0e6));
  }
  auto coordinate = [&](const Vec3& p, int a) {
    const double c = std::floor((p[a] - lo[a]) / cell);
    return std::min(static_cast<std::uint64_t>(std::max(c, 0.0)), cells[a] - 1);
  };
  std::vector<std::uint64_t> key(n);
  for (std::size_t i = 0; i < n; ++i)
    key[i] = (coordinate(x[i], 2) * cells[1] + coordinate(x[i], 1)) * cells[0] + coordinate(x[i], 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  return order;
}

}  // namespace wearscale::dem
