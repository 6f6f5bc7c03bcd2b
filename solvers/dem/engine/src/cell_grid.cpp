#include "wearscale/dem/cell_grid.hpp"

#include <algorithm>
#include <cmath>

namespace wearscale::dem {

void CellGrid::build(std::span<const Vec3> x, const Box& box, double cut, int threads) {
  const std::size_t n = x.size();
  images_ = PeriodicImages::within(box, cut);
  images_.vectors(box, shift_.data());
  // The box on periodic axes, the particles' extent on open ones.
  Vec3 lo{}, length{};
  for (int a = 0; a < 3; ++a) {
    const auto ua = static_cast<std::size_t>(a);
    periodic_[ua] = box.periodic[ua];
    if (periodic_[ua]) {
      lo[a] = box.lo[a];
      length[a] = box.hi[a] - box.lo[a];
    } else {
      double mn = 0.0, mx = 0.0;
      if (n > 0) {
        mn = mx = x[0][a];
        // On the threads that moved the particles last (their positions
        // are in those cores' caches).
#pragma omp parallel for schedule(static) reduction(min : mn) reduction(max : mx) num_threads(threads) if (threads > 1)
        for (std::size_t k = 0; k < n; ++k) {
          mn = std::min(mn, x[k][a]);
          mx = std::max(mx, x[k][a]);
        }
      }
      lo[a] = mn;
      length[a] = std::max(mx - mn, cut) * (1.0 + 1e-12);
    }
    cells_[ua] = std::clamp(static_cast<int>(std::floor(length[a] / cut)), 1, 1 << 20);
  }
  // No more cells than a few per particle (a lone particle far away on an
  // open axis would otherwise ask for a huge grid); cells only grow.
  auto product = [&] {
    return static_cast<double>(cells_[0]) * static_cast<double>(cells_[1]) * static_cast<double>(cells_[2]);
  };
  while (product() > 4.0 * static_cast<double>(n) + 64.0) {
    auto& largest = *std::max_element(cells_.begin(), cells_.end());
    largest = std::max(1, largest / 2);
  }
  Vec3 size{};
  half_stencil_ = true;
  for (std::size_t a = 0; a < 3; ++a) {
    const int ia = static_cast<int>(a);
    size[ia] = length[ia] / cells_[a];
    // Cells no smaller than the cutoff (to rounding: L/⌊L/cut⌋) reach one
    // cell over; thinner ones (a periodic length below the cutoff) as many
    // as the cutoff spans.
    span_[a] = size[ia] >= cut * (1.0 - 1e-12) ? 1 : static_cast<int>(std::ceil(cut / size[ia]));
    if (span_[a] > 1 || (periodic_[a] && cells_[a] < 3)) half_stencil_ = false;
  }

  const std::size_t ncell = static_cast<std::size_t>(cells_[0]) * static_cast<std::size_t>(cells_[1]) *
                            static_cast<std::size_t>(cells_[2]);
  if (scratch_.size() < n) scratch_.resize(n);
  std::uint32_t* cell = scratch_.data();
  order_.resize(n);
  auto coordinate = [&](const Vec3& xi, int a) {
    const int c = static_cast<int>(std::floor((xi[a] - lo[a]) / size[a]));
    return std::clamp(c, 0, cells_[static_cast<std::size_t>(a)] - 1);
  };
  // Each particle's cell (over the threads), then the particles sorted by
  // cell, in increasing index within a cell (a counting sort): a cell's
  // particles are one run of order_, read front to back by the search.
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (std::size_t k = 0; k < n; ++k)
    cell[k] = static_cast<std::uint32_t>(flat(coordinate(x[k], 0), coordinate(x[k], 1), coordinate(x[k], 2)));
  start_.assign(ncell + 1, 0);
  for (std::size_t k = 0; k < n; ++k) ++start_[cell[k] + 1];
  for (std::size_t c = 0; c < ncell; ++c) start_[c + 1] += start_[c];
  for (std::size_t k = 0; k < n; ++k) order_[start_[cell[k]]++] = static_cast<std::uint32_t>(k);
  for (std::size_t c = ncell; c > 0; --c) start_[c] = start_[c - 1];  // each cursor ended at the next cell's start
  start_[0] = 0;
  if (half_stencil_) sort_positions(x, threads);
}

// The positions in slot order, in single precision, for for_each_run's
// callers: a cell's and a row's particles side by side.
void CellGrid::sort_positions(std::span<const Vec3> x, int threads) {
  const std::size_t n = x.size();
  for (auto& axis : sorted_) {
    axis.resize(n + 3);  // vectors of four may read past the last slot
    std::fill_n(axis.begin() + static_cast<std::ptrdiff_t>(n), 3, 0.0f);
  }
  float* sx = sorted_[0].data();
  float* sy = sorted_[1].data();
  float* sz = sorted_[2].data();
  double largest = 0.0;  // |x| over every coordinate
#pragma omp parallel for schedule(static) reduction(max : largest) num_threads(threads) if (threads > 1)
  for (std::size_t b = 0; b < n; ++b) {
    const Vec3& xb = x[order_[b]];
    sx[b] = static_cast<float>(xb.x);
    sy[b] = static_cast<float>(xb.y);
    sz[b] = static_cast<float>(xb.z);
    largest = std::max({largest, std::abs(xb.x), std::abs(xb.y), std::abs(xb.z)});
  }
  double shift = 0.0;
  for (int k = 0; k < images_.count(); ++k) {
    const Vec3& sk = shift_[static_cast<std::size_t>(k)];
    shift = std::max({shift, std::abs(sk.x), std::abs(sk.y), std::abs(sk.z)});
  }
  // x_j and xs = shift − x_i (|xs| ≤ M + S) each rounded to float (2⁻²⁴
  // relative), their float sum rounded (|sum| ≤ 2M + S) and the double sum's
  // own rounding: below 2⁻²⁴ (4M + 2S) and a little; 2⁻²¹ (M + S) covers it.
  sorted_error_ = std::ldexp(largest + shift, -21);
}

std::pair<int, int> CellGrid::layer_range(int part, int parts) const {
  // Layer l's particles start at start_[l × (cells a layer)] (z is the slowest index).
  const std::size_t layer_cells = static_cast<std::size_t>(cells_[0]) * static_cast<std::size_t>(cells_[1]);
  auto begin = [&](int t) {
    if (t <= 0) return 0;
    if (t >= parts) return cells_[2];
    const std::size_t share = start_.back() * static_cast<std::size_t>(t) / static_cast<std::size_t>(parts);
    // The first layer starting at or past the share; the layer past the last starts at n ≥ share.
    int l = 0;
    while (start_[static_cast<std::size_t>(l) * layer_cells] < share) ++l;
    return l;
  };
  return {begin(part), begin(part + 1)};
}

}  // namespace wearscale::dem
