#pragma once
// The walk of (4.25) over rows of a labelled contact map, shared by the whole
// map's check (crack_initiation.cpp) and the check of a map held in slabs
// (slab_crack_initiation.cpp): a point of a micro-contact and its
// 4-neighbour out of it make an edge, trailing when the neighbour lies behind
// along the sliding direction ê, leading when it lies ahead. Private to bem.
#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "wearscale/bem/crack_initiation.hpp"
#include "wearscale/core/grid.hpp"

namespace wearscale::bem::detail {

/// One row of the map: the points' micro-contacts (−1 outside), σ_I and σ_III.
struct MapRow {
  const int* label;
  const double* first;
  const double* third;
};

/// ê, after refusing σ_m ≤ 0 and a zero or non-finite direction (InputError).
std::array<double, 2> sliding_direction(double dir_x, double dir_y, double sigma_m);

/// Checks of `clusters` micro-contacts with no edge met yet (trailing −∞, leading +∞).
std::vector<EdgeCrackCheck> unmet_edges(std::size_t clusters);

/// The edges of the points of rows [0, rows) of `whole`'s columns (periodic
/// along y): row_at(i) gives row i for i in [−1, rows], the rows next to the
/// two ends included. Raises each micro-contact's trailing σ_I and lowers its
/// leading σ_III in `checks`.
template <class RowAt>
void walk_edges(std::size_t rows, const Grid2D& whole, std::array<double, 2> e, RowAt row_at,
                std::vector<EdgeCrackCheck>& checks) {
  const long ny = static_cast<long>(whole.ny);
  const double along_x = whole.dx() * e[0], along_y = whole.dy() * e[1], eps = 1e-12 * whole.dx();
  // The four steps (rows, columns) and how far each goes along ê.
  const long steps[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  double along[4];
  for (int s = 0; s < 4; ++s)
    along[s] = static_cast<double>(steps[s][0]) * along_x + static_cast<double>(steps[s][1]) * along_y;
  for (std::size_t i = 0; i < rows; ++i) {
    const MapRow row = row_at(static_cast<long>(i));
    const MapRow above = row_at(static_cast<long>(i) + 1), below = row_at(static_cast<long>(i) - 1);
    for (long j = 0; j < ny; ++j) {
      const int id = row.label[j];
      if (id < 0) continue;
      EdgeCrackCheck& c = checks[static_cast<std::size_t>(id)];
      for (int s = 0; s < 4; ++s) {
        const MapRow& other = steps[s][0] > 0 ? above : steps[s][0] < 0 ? below : row;
        const long jn = ((j + steps[s][1]) % ny + ny) % ny;
        if (other.label[jn] == id) continue;  // inside the same micro-contact: no border
        if (along[s] < -eps)  // the neighbour lies behind: trailing edge (a)
          c.trailing_tension = std::max({c.trailing_tension, row.first[j], other.first[jn]});
        else if (along[s] > eps)  // ahead: leading edge (b)
          c.leading_compression = std::min({c.leading_compression, row.third[j], other.third[jn]});
      }
    }
  }
}

/// The criteria from the extremes: (4.25a) and (4.25b).
void decide(std::vector<EdgeCrackCheck>& checks, double sigma_m);

}  // namespace wearscale::bem::detail
