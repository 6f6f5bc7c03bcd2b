#include "wearscale/bem/harmonic_fill.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "wearscale/core/errors.hpp"

namespace wearscale::bem {

std::size_t harmonic_fill(RealField& h, std::span<const std::uint8_t> missing) {
  const Grid2D& g = h.grid();
  if (missing.size() != h.size()) throw std::invalid_argument("harmonic_fill: one missing flag per point is needed");
  // Unknowns: the missing points, numbered in storage order.
  std::vector<long> unknown(h.size(), -1);
  long n = 0;
  for (std::size_t k = 0; k < h.size(); ++k)
    if (missing[k] != 0) unknown[k] = n++;
  if (n == 0) return 0;
  if (static_cast<std::size_t>(n) == h.size()) throw std::invalid_argument("harmonic_fill: no point is measured");

  // Σ_q w_pq (h_p − h_q) = 0 at every missing p over its neighbours q in
  // the grid: symmetric positive definite, every hole touching a measured point.
  // Weights 1/dx², 1/dy² scaled so the larger is 1 (the smaller kept above
  // 1e-12 so that no direction decouples), heights scaled to at most 1 in
  // magnitude: the solution lies between the measured values (maximum
  // principle), so nothing can overflow whatever the file's numbers.
  const double ratio = g.dx() / g.dy();
  const double wx = ratio <= 1.0 ? 1.0 : std::max(1.0 / (ratio * ratio), 1e-12);
  const double wy = ratio <= 1.0 ? std::max(ratio * ratio, 1e-12) : 1.0;
  double scale = 0.0;
  for (std::size_t k = 0; k < h.size(); ++k)
    if (unknown[k] < 0) scale = std::max(scale, std::abs(h[k]));
  if (!std::isfinite(scale)) throw std::invalid_argument("harmonic_fill: a measured height is not finite");
  if (scale == 0.0) scale = 1.0;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(n) * 5);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) {
      const long p = unknown[g.index(i, j)];
      if (p < 0) continue;
      double diagonal = 0.0;
      auto neighbour = [&](std::size_t ni, std::size_t nj, double w) {
        diagonal += w;
        const std::size_t q = g.index(ni, nj);
        if (unknown[q] >= 0)
          entries.emplace_back(p, unknown[q], -w);
        else
          rhs[p] += w * (h[q] / scale);
      };
      if (i > 0) neighbour(i - 1, j, wx);
      if (i + 1 < g.nx) neighbour(i + 1, j, wx);
      if (j > 0) neighbour(i, j - 1, wy);
      if (j + 1 < g.ny) neighbour(i, j + 1, wy);
      entries.emplace_back(p, p, diagonal);
    }
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(a);
  if (solver.info() != Eigen::Success)
    throw NumericalError("harmonic fill", 0, "missing heights", "the Laplace system could not be factorised");
  const Eigen::VectorXd filled = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !filled.allFinite())
    throw NumericalError("harmonic fill", 0, "missing heights", "the Laplace system could not be solved");
  for (std::size_t k = 0; k < h.size(); ++k)
    if (unknown[k] >= 0) h[k] = scale * filled[unknown[k]];
  return static_cast<std::size_t>(n);
}

}  // namespace wearscale::bem
