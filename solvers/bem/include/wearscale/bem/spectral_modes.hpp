#pragma once
// The modes of the r2c spectrum of a surface seen as radial wavenumbers.
//
// Rough-surface parameters are integer-like wavenumbers k, with q = 2πk/L
// (thesis §1.1.2, Fig. 1.3). On an Lx × Ly grid, L is the longer side, so
// k = 1 is the fundamental of the longest direction; on a square grid mode
// (kx, ky) has k = √(kx² + ky²).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

#include "wearscale/core/grid.hpp"

namespace wearscale::bem {

/// L in q = 2πk/L: the longer side of the grid.
inline double reference_length(const Grid2D& g) { return std::max(g.lx, g.ly); }

/// Δq = 2π/L: the unit of radial wavenumbers (and the width of radial PSD bins).
inline double wavenumber_unit(const Grid2D& g) { return 2.0 * std::numbers::pi / reference_length(g); }

/// k = L·√((kx/Lx)² + (ky/Ly)²) of r2c mode (i, j), from the integer
/// frequencies kx, ky (exact, e.g. 5 for (3, 4), on a square domain).
inline double radial_wavenumber(const Grid2D& g, std::size_t i, std::size_t j) {
  const double l = reference_length(g);
  return std::hypot(static_cast<double>(g.frequency_x(i)) * (l / g.lx), static_cast<double>(g.frequency_y(j)) * (l / g.ly));
}

/// |q| = √(qx² + qy²) = 2πk/L of r2c mode (i, j) [rad/m].
inline double radial_q(const Grid2D& g, std::size_t i, std::size_t j) {
  return radial_wavenumber(g, i, j) * wavenumber_unit(g);
}

/// Relative slack when a radial wavenumber is compared with a bound, so that
/// round-off in k on non-square domains never moves a mode across it.
inline constexpr double wavenumber_slack = 1e-9;

/// The highest radial wavenumber whose whole circle the grid resolves:
/// min(nx·L/Lx, ny·L/Ly)/2, i.e. min(nx, ny)/2 on a square domain.
inline double nyquist_wavenumber(const Grid2D& g) {
  const double l = reference_length(g);
  return 0.5 * std::min(static_cast<double>(g.nx) * l / g.lx, static_cast<double>(g.ny) * l / g.ly);
}

/// How many modes of the full nx × ny spectrum r2c column j stands for: the
/// columns 0 < j < ny/2 also hold, by Hermitian symmetry, the modes (−i, −j);
/// column 0 and, for even ny, column ny/2 are their own mirror image.
inline double mode_multiplicity(const Grid2D& g, std::size_t j) {
  return (j == 0 || 2 * j == g.ny) ? 1.0 : 2.0;
}

/// f(i, j, m) for every mode (i, j) of the r2c half spectrum, m = i·(ny/2+1) + j
/// its storage index; rows in parallel.
template <class F>
void for_each_mode(const Grid2D& g, F&& f) {
  const std::size_t rows = g.nx, cols = g.spectral_ny();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < rows; ++i)
    for (std::size_t j = 0; j < cols; ++j) f(i, j, i * cols + j);
}

/// The sum over the whole nx × ny spectrum of a Hermitian-symmetric quantity
/// known on the r2c half: term(m, w, sum) adds w times the value of stored mode
/// m to `sum` (an accumulator with +=), w = mode_multiplicity. Parseval's
/// Σ_x a(x) b(x) = (1/N) Σ_q â(q) conj(b̂(q)) is its main use.
template <class Sum, class Term>
Sum hermitian_sum(const Grid2D& g, Term&& term) {
  const std::size_t rows = g.nx, cols = g.spectral_ny();
  const std::size_t last = g.ny % 2 == 0 ? cols - 1 : cols;  // the Nyquist column is its own mirror
  Sum total{};
#pragma omp parallel
  {
    Sum local{};
#pragma omp for schedule(static) nowait
    for (std::size_t i = 0; i < rows; ++i) {
      Sum row{};
      for (std::size_t j = 0; j < cols; ++j) term(i * cols + j, (j == 0 || j == last) ? 1.0 : 2.0, row);
      local += row;
    }
#pragma omp critical(wearscale_hermitian_sum)
    total += local;
  }
  return total;
}

}  // namespace wearscale::bem
