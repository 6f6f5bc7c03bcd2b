#include "wearscale/bem/half_space.hpp"

#include <cmath>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::bem {

namespace {
using cplx = std::complex<double>;

void check_material(double e, double nu) {
  if (!(e > 0.0) || !std::isfinite(e))
    throw InputError(fmt::format("elastic half-space: Young's modulus E = {} is not allowed; allowed: E > 0", e));
  if (!(nu > -1.0 && nu <= 0.5))
    throw InputError(fmt::format(
        "elastic half-space: Poisson's ratio ν = {} is not allowed; allowed: −1 < ν ≤ 0.5", nu));
}
}  // namespace

HalfSpace::HalfSpace(const Grid2D& grid, double young, double poisson)
    : grid_(grid), young_(young), poisson_(poisson) {
  check_material(young, poisson);
  if (grid.nx < 2 || grid.ny < 2 || !(grid.lx > 0) || !(grid.ly > 0))
    throw InputError(fmt::format("elastic half-space: grid {} is not allowed; allowed: ≥ 2×2 points, sizes > 0",
                                 grid.to_string()));
  plan_ = FFTPlanCache::global().plan(grid);
  for (ComplexField* f : {&px_, &py_, &pz_, &ux_, &uy_, &uz_}) *f = ComplexField::spectrum_of(grid);
}

GreenTensor HalfSpace::green_tensor(double qx, double qy, double g, double nu, bool odd_x, bool odd_y) {
  GreenTensor f{};
  const double q2 = qx * qx + qy * qy;
  if (q2 == 0.0) return f;
  const double q = std::sqrt(q2);
  const double s = 1.0 / (g * q);
  const double c = 0.5 * (1.0 - 2.0 * nu) / q;  // coupling (4.22), odd in q
  const cplx xz(0.0, odd_x ? s * c * qx : 0.0), yz(0.0, odd_y ? s * c * qy : 0.0);
  f[0][0] = s * (1.0 - nu * qx * qx / q2);  // Cerruti, in-line (4.3)
  f[1][1] = s * (1.0 - nu * qy * qy / q2);
  f[0][1] = f[1][0] = -s * nu * qx * qy / q2;
  f[0][2] = xz;  // u_x from p_z (2.35a)
  f[1][2] = yz;
  f[2][0] = std::conj(xz);  // u_z from p_x = −u_x from p_z reflected (4.22)
  f[2][1] = std::conj(yz);
  f[2][2] = s * (1.0 - nu);  // Boussinesq (2.35c)
  return f;
}

void HalfSpace::displacement(const VectorField& p, VectorField& u) {
  plan_->forward(p.x, px_);
  plan_->forward(p.y, py_);
  plan_->forward(p.z, pz_);
  const double g = shear_modulus(), nu = poisson_;
  const std::size_t rows = px_.rows(), cols = px_.cols();
  const bool nyq_x = grid_.nx % 2 == 0, nyq_y = grid_.ny % 2 == 0;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < rows; ++i) {
    const double qx = grid_.wavenumber_x(i);
    const bool odd_x = !(nyq_x && i == grid_.nx / 2);
    for (std::size_t j = 0; j < cols; ++j) {
      const auto f = green_tensor(qx, grid_.wavenumber_y(j), g, nu, odd_x, !(nyq_y && j == grid_.ny / 2));
      const cplx a = px_(i, j), b = py_(i, j), c = pz_(i, j);
      ux_(i, j) = f[0][0] * a + f[0][1] * b + f[0][2] * c;
      uy_(i, j) = f[1][0] * a + f[1][1] * b + f[1][2] * c;
      uz_(i, j) = f[2][0] * a + f[2][1] * b + f[2][2] * c;
    }
  }
  plan_->backward(ux_, u.x);
  plan_->backward(uy_, u.y);
  plan_->backward(uz_, u.z);
}

void HalfSpace::normal_displacement(const RealField& p, RealField& u) {
  plan_->forward(p, pz_);
  const double s = 2.0 / (contact_modulus() * static_cast<double>(grid_.size()));  // 1/N of the inverse folded in
  const std::size_t rows = pz_.rows(), cols = pz_.cols();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < rows; ++i) {
    const double qx = grid_.wavenumber_x(i);
    for (std::size_t j = 0; j < cols; ++j) {
      const double qy = grid_.wavenumber_y(j);
      const double q = std::sqrt(qx * qx + qy * qy);
      pz_(i, j) *= q > 0.0 ? s / q : 0.0;
    }
  }
  plan_->backward_unnormalized(pz_, u);
}

double HalfSpace::elastic_energy(const VectorField& p, const VectorField& u) {
  return elastic_energy(p.x, u.x) + elastic_energy(p.y, u.y) + elastic_energy(p.z, u.z);
}

double HalfSpace::elastic_energy(const RealField& p, const RealField& u) {
  double sum = 0.0;
  const std::size_t n = p.size();
#pragma omp parallel for reduction(+ : sum) schedule(static)
  for (std::size_t k = 0; k < n; ++k) sum += p[k] * u[k];
  return 0.5 * sum * p.grid().cell_area();
}

}  // namespace wearscale::bem
