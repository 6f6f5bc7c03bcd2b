#include "wearscale/wear/tangential_compliance.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::wear {

namespace {
// Antiderivatives over x and y of the two terms of (4.3), up to terms in x or y
// alone (they cancel in the corner sum): ∫∫ 1/r = x asinh(y/|x|) + y asinh(x/|y|),
// ∫∫ x²/r³ = y asinh(x/|y|).
double x_asinh(double x, double y) { return x == 0.0 ? 0.0 : x * std::asinh(y / std::abs(x)); }
}  // namespace

double TangentialCompliance::cell_kernel(double di, double dj, double h, double g, double nu) {
  const double x0 = (di - 0.5) * h, x1 = (di + 0.5) * h, y0 = (dj - 0.5) * h, y1 = (dj + 0.5) * h;
  auto f = [&](double x, double y) { return 2.0 * (1.0 - nu) * x_asinh(x, y) + 2.0 * x_asinh(y, x); };
  return (f(x1, y1) - f(x0, y1) - f(x1, y0) + f(x0, y0)) / (4.0 * std::numbers::pi * g);  // (4.3) over a cell
}

TangentialCompliance::TangentialCompliance(const Grid2D& grid, double g, double nu)
    : grid_(grid), padded_(2 * grid.nx, 2 * grid.ny, 2 * grid.lx, 2 * grid.ly), shear_modulus_(g), poisson_(nu) {
  if (!(g > 0.0) || !std::isfinite(g))
    throw InputError(fmt::format("tangential compliance: shear modulus G = {} is not allowed; allowed: G > 0", g));
  if (!(nu > -1.0 && nu <= 0.5))
    throw InputError(fmt::format("tangential compliance: ν = {} is not allowed; allowed: −1 < ν ≤ 0.5", nu));
  if (std::abs(grid.dx() - grid.dy()) > 1e-12 * grid.dx() || grid.nx < 2 || grid.ny < 2)
    throw InputError(fmt::format("tangential compliance: grid {} is not allowed; allowed: square cells, ≥ 2 × 2",
                                 grid.to_string()));
  const double h = grid.dx();
  table_.resize(grid.nx * grid.ny);
  for (std::size_t a = 0; a < grid.nx; ++a)
    for (std::size_t b = 0; b < grid.ny; ++b)
      table_[a * grid.ny + b] = cell_kernel(static_cast<double>(a), static_cast<double>(b), h, g, nu);
  plan_ = FFTPlanCache::global().plan(padded_);
  RealField k(padded_);
  const long nx = static_cast<long>(grid.nx), ny = static_cast<long>(grid.ny);
  for (long di = -(nx - 1); di < nx; ++di)
    for (long dj = -(ny - 1); dj < ny; ++dj) k[padded_.periodic_index(di, dj)] = kernel(di, dj);
  ComplexField s = ComplexField::spectrum_of(padded_);
  plan_->forward(k, s);
  const double inv = 1.0 / static_cast<double>(padded_.size());
  spectrum_.resize(s.size());
  for (std::size_t m = 0; m < s.size(); ++m) spectrum_[m] = s[m] * inv;
}

TangentialCompliance::Workspace TangentialCompliance::workspace() const {
  return Workspace{RealField(padded_), ComplexField::spectrum_of(padded_)};
}

void TangentialCompliance::displacement(const RealField& p, RealField& u, Workspace& w) const {
  w.padded.fill(0.0);
  for (std::size_t i = 0; i < grid_.nx; ++i)
    for (std::size_t j = 0; j < grid_.ny; ++j) w.padded(i, j) = p(i, j);
  plan_->forward(w.padded, w.spectrum);
  for (std::size_t m = 0; m < spectrum_.size(); ++m) w.spectrum[m] *= spectrum_[m];
  plan_->backward_unnormalized(w.spectrum, w.padded);
  for (std::size_t i = 0; i < grid_.nx; ++i)
    for (std::size_t j = 0; j < grid_.ny; ++j) u(i, j) = w.padded(i, j);
}

double TangentialCompliance::energy(const RealField& p, const RealField& u) const {
  double sum = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) sum += p[k] * u[k];
  return 0.5 * grid_.cell_area() * sum;  // (4.2)
}

}  // namespace wearscale::wear
