#pragma once
// Candidate wear particles of the numerical model (§5.1, step 1): discs whose
// diameter joins, along the sliding direction x, a trailing-edge point (a)
// where σ_I ≥ σ_m to a leading-edge point (b) where σ_III ≤ −σ_m — the two
// diametrically opposed crack nucleation sites of Fig. 4.2 and (4.25). The
// stresses are those of the tangential traction σ_j on every contact point
// (subsurface_stress.hpp at the surface), the loading of Fig. 4.1.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "wearscale/wear/micro_contact_map.hpp"

namespace wearscale::wear {

/// A disc on the grid: its diameter along x runs over `cells` grid cells, from
/// the trailing-edge cell (i, j) to the leading-edge cell (i + cells − 1, j).
/// Its centre is at cell coordinates (i + (cells − 1)/2, j), its diameter is
/// cells·Δx, and it holds the cells of the window whose centres lie within
/// cells/2 of that centre.
struct Disc {
  long i = 0, j = 0;
  long cells = 1;
  double centre_i() const { return static_cast<double>(i) + 0.5 * static_cast<double>(cells - 1); }
  double radius_cells() const { return 0.5 * static_cast<double>(cells); }
  double diameter(const Grid2D& g) const { return static_cast<double>(cells) * g.dx(); }
  /// The disc's cells in the window, row by row: f(row j, first i, last i).
  template <class F>
  void for_each_row(const Grid2D& g, F&& f) const;
};

/// Crack nucleation sites (4.25) per contact point: trailing[k] when the point
/// is a trailing edge of its micro-contact (no contact at −x), σ_I = max σ_I
/// over it and that neighbour ≥ σ_m (4.25a), and σ_I is within the fraction
/// `spot` of the largest σ_I on that micro-contact's trailing edge — the
/// spot where its crack nucleates first (Fig. 5.3); leading[k] likewise with
/// the +x neighbour and −σ_III. spot = 1 keeps every edge point past σ_m.
struct CrackSites {
  std::vector<std::uint8_t> trailing, leading;
  double max_tension = 0.0;      ///< largest σ_I found on a trailing edge [Pa]
  double max_compression = 0.0;  ///< largest −σ_III found on a leading edge [Pa]
};

/// Surface stresses of p_x = σ_j on the contact and the sites above.
/// InputError unless σ_j > 0, σ_m > 0, −1 < ν ≤ 0.5 and 0 ≤ spot ≤ 1.
CrackSites crack_sites(const MicroContactMap& map, double junction_strength, double poisson, double tensile_strength,
                       double spot = 1.0);

/// Every disc from a trailing site to a leading site ahead of it on the same
/// row (the window is not periodic), at most max_cells ≤ n long, largest first (ties: by row, then by x, so the order is deterministic).
std::vector<Disc> candidate_particles(const MicroContactMap& map, const CrackSites& sites, long max_cells);

// ---------------------------------------------------------------------------
template <class F>
void Disc::for_each_row(const Grid2D& g, F&& f) const {
  const double r = radius_cells(), c = centre_i();
  const long rows = static_cast<long>(std::floor(r + 1e-9));
  for (long dj = -rows; dj <= rows; ++dj) {
    const double w2 = r * r - static_cast<double>(dj * dj);
    if (w2 < -1e-9) continue;
    const double w = std::sqrt(std::max(w2, 0.0));
    const long row = j + dj;
    if (row < 0 || row >= static_cast<long>(g.ny)) continue;
    const long first = std::max(0L, static_cast<long>(std::ceil(c - w - 1e-9)));
    const long last = std::min(static_cast<long>(g.nx) - 1, static_cast<long>(std::floor(c + w + 1e-9)));
    if (last >= first) f(row, first, last);
  }
}

}  // namespace wearscale::wear
