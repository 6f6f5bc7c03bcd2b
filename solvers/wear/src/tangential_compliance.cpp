#include "wearscale/wear/tangential_compliance.hpp"

#include <cmath>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::wear {

namespace {
const Grid2D& checked(const Grid2D& grid, double g, double nu) {
  if (!(g > 0.0) || !std::isfinite(g))
    throw InputError(fmt::format("tangential compliance: shear modulus G = {} is not allowed; allowed: G > 0", g));
  if (!(nu > -1.0 && nu <= 0.5))
    throw InputError(fmt::format("tangential compliance: ν = {} is not allowed; allowed: −1 < ν ≤ 0.5", nu));
  if (std::abs(grid.dx() - grid.dy()) > 1e-12 * grid.dx() || grid.nx < 2 || grid.ny < 2)
    throw InputError(fmt::format("tangential compliance: grid {} is not allowed; allowed: square cells, ≥ 2 × 2",
                                 grid.to_string()));
  return grid;
}
}  // namespace

TangentialCompliance::TangentialCompliance(const Grid2D& grid, double g, double nu)
    : body_(bem::HalfSpace::from_shear_modulus(checked(grid, g, nu), g, nu, bem::Boundary::Free,
                                               bem::Response::ShearX)) {
  const double h = grid.dx();
  const std::size_t ny = grid.ny;
  padded_ny_ = (ny + 7) / 8 * 8;
  const std::size_t stride = 2 * padded_ny_;
  table_.assign(grid.nx * stride, 0.0);
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < grid.nx; ++a) {
    double* row = table_.data() + a * stride + padded_ny_;
    for (std::size_t b = 0; b < ny; ++b) {
      const double v = cell_kernel(static_cast<double>(a), static_cast<double>(b), h, g, nu);
      row[b] = v;
      row[-static_cast<long>(b)] = v;
    }
  }
  cumulative_.assign((grid.nx + 1) * stride, 0.0);
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < ny; ++b) {
    long double sum = 0.0L;
    for (std::size_t a = 0; a <= grid.nx; ++a) {
      double* row = cumulative_.data() + a * stride + padded_ny_;
      row[b] = row[-static_cast<long>(b)] = static_cast<double>(sum);
      if (a < grid.nx) sum += table_[a * stride + padded_ny_ + b];
    }
  }
}

double TangentialCompliance::energy(const RealField& p, const RealField& u) const {
  double sum = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) sum += p[k] * u[k];
  return 0.5 * grid().cell_area() * sum;  // (4.2)
}

}  // namespace wearscale::wear
