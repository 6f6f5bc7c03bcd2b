#include "wearscale/bem/slab_crack_initiation.hpp"

#include <stdexcept>

#include "edge_walk.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/core/row_halo.hpp"

namespace wearscale::bem {

std::vector<EdgeCrackCheck> crack_initiation_slab(const SlabContactMap& map, const PrincipalStresses& stress,
                                                  std::size_t first_row, const Grid2D& whole, double dir_x,
                                                  double dir_y, double sigma_m) {
  const auto e = detail::sliding_direction(dir_x, dir_y, sigma_m);
  const Grid2D& local = stress.first.grid();
  const std::size_t rows = local.nx, ny = whole.ny;
  if (local.ny != ny || map.label.size() != local.size())
    throw std::invalid_argument("crack_initiation_slab: contact map, stresses and grid differ");
  std::vector<EdgeCrackCheck> checks = detail::unmet_edges(map.count);
  if (map.count == 0) return checks;  // every rank alike: the count is the whole map's

  // The rows next to the slab: labels (exact as doubles), σ_I, σ_III.
  std::vector<double> first(3 * ny), last(3 * ny), before(3 * ny), after(3 * ny);
  const auto pack = [&](std::size_t row, std::vector<double>& out) {
    for (std::size_t j = 0; j < ny; ++j) {
      const std::size_t k = row * ny + j;
      out[j] = static_cast<double>(map.label[k]);
      out[ny + j] = stress.first[k];
      out[2 * ny + j] = stress.third[k];
    }
  };
  if (rows > 0) {
    pack(0, first);
    pack(rows - 1, last);
  }
  exchange_row_halo({first_row, rows}, first, last, before, after);
  std::vector<int> before_label(ny), after_label(ny);
  for (std::size_t j = 0; j < ny; ++j) {
    before_label[j] = static_cast<int>(before[j]);
    after_label[j] = static_cast<int>(after[j]);
  }
  detail::walk_edges(rows, whole, e, [&](long i) {
    if (i < 0) return detail::MapRow{before_label.data(), before.data() + ny, before.data() + 2 * ny};
    if (i >= static_cast<long>(rows)) return detail::MapRow{after_label.data(), after.data() + ny, after.data() + 2 * ny};
    const std::size_t at = static_cast<std::size_t>(i) * ny;
    return detail::MapRow{map.label.data() + at, stress.first.data() + at, stress.third.data() + at};
  }, checks);

  // The ranks' extremes per micro-contact.
  std::vector<double> trailing(checks.size()), leading(checks.size());
  for (std::size_t c = 0; c < checks.size(); ++c) {
    trailing[c] = checks[c].trailing_tension;
    leading[c] = checks[c].leading_compression;
  }
  mpi::max(trailing);
  mpi::min(leading);
  for (std::size_t c = 0; c < checks.size(); ++c) {
    checks[c].trailing_tension = trailing[c];
    checks[c].leading_compression = leading[c];
  }
  detail::decide(checks, sigma_m);
  return checks;
}

}  // namespace wearscale::bem
