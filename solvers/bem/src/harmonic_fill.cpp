#include "wearscale/bem/harmonic_fill.hpp"

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
  const double wx = 1.0 / (g.dx() * g.dx()), wy = 1.0 / (g.dy() * g.dy());
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
          rhs[p] += w * h[q];
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
    if (unknown[k] >= 0) h[k] = filled[unknown[k]];
  return static_cast<std::size_t>(n);
}

}  // namespace wearscale::bem
