#pragma once
// Internal to the tribometer library: the compliance of an implicit stage's wear.
#include <span>
#include <vector>

#include "wearscale/tribometer/pin_on_disc.hpp"

namespace wearscale::tribometer {

// The wear of an implicit stage as a compliance (bem::AddedCompliance): over
// the stage (length γ) a cell of the pin recedes by γ s p/p_crit (9.23)-(9.24),
// a diagonal term w p, and a column of the averaged disc by the column mean
// of γ (1 − s) p/p_crit scaled by L/L_path, a term c_i mean_j(p) per column
// (its part that differs along the column is iterated on in solve_stage).
//
// Its preconditioner M = (κ I + A)⁻¹ inverts the stage's compliance A exactly
// (the diagonal w, and the column term per column by Sherman–Morrison) and
// the half-space by its diagonal κ = K(0), a cell's own compliance. Where the
// wear's compliance dominates the half-space's (long stages, cells on the
// oxide) M is close to (K + A)⁻¹; where there is none (the pin on the
// substrate) it is K's Jacobi. The half-space's S alone does not fit K + A:
// it is the inverse of K, and w is up to 100× K(0) (docs/pin_on_disc.md).
struct PinOnDisc::StageCompliance final : bem::AddedCompliance {
  std::vector<double> w;  // per cell [m/Pa]
  std::vector<double> c;  // per column [m/Pa]
  std::size_t ny = 0;
  double kappa = 0.0;     // K(0) [m/Pa]
  std::vector<double> readmit;  // 1/(κ + w) per cell [Pa/m]

  void add(const RealField& p, double scale, RealField& u) const override {
    const std::size_t nx = c.size();
    for (std::size_t i = 0; i < nx; ++i) {
      const double* pi = p.data() + i * ny;
      double* ui = u.data() + i * ny;
      const double* wi = w.data() + i * ny;
      double column = 0.0;
      for (std::size_t j = 0; j < ny; ++j) column += pi[j];
      const double shift = scale * c[i] * column / static_cast<double>(ny);
      for (std::size_t j = 0; j < ny; ++j) ui[j] += scale * wi[j] * pi[j] + shift;
    }
  }
  bool has_preconditioner() const override { return kappa > 0.0; }
  void precondition(const RealField& r, RealField& z) const override {
    const std::size_t nx = c.size();
    const double f_scale = 1.0 / static_cast<double>(ny);
    for (std::size_t i = 0; i < nx; ++i) {
      const double* ri = r.data() + i * ny;
      const double* wi = w.data() + i * ny;
      double* zi = z.data() + i * ny;
      double sum_z = 0.0, sum_d = 0.0;
      for (std::size_t j = 0; j < ny; ++j) {
        const double d = 1.0 / (kappa + wi[j]);
        zi[j] = d * ri[j];
        sum_z += zi[j];
        sum_d += d;
      }
      // (D + f 1 1ᵀ)⁻¹ r = D⁻¹ r − D⁻¹ 1 · f (1ᵀ D⁻¹ r) / (1 + f 1ᵀ D⁻¹ 1), D = κ + w, f = c_i/n_y
      const double f = c[i] * f_scale;
      const double shift = f * sum_z / (1.0 + f * sum_d);
      for (std::size_t j = 0; j < ny; ++j) zi[j] -= shift / (kappa + wi[j]);
    }
  }
  // M at offset 0 per cell, the column term left out: 1/(κ + w).
  std::span<const double> precondition_diagonal() const override { return readmit; }
  void set_diagonal() {
    readmit.resize(w.size());
    for (std::size_t k = 0; k < w.size(); ++k) readmit[k] = 1.0 / (kappa + w[k]);
  }
  double quadratic_form(const RealField& t) const override {
    double sum = 0.0;
    for (std::size_t i = 0; i < c.size(); ++i) {
      const double* ti = t.data() + i * ny;
      const double* wi = w.data() + i * ny;
      double column = 0.0;
      for (std::size_t j = 0; j < ny; ++j) {
        column += ti[j];
        sum += wi[j] * ti[j] * ti[j];
      }
      sum += c[i] * column * column / static_cast<double>(ny);
    }
    return sum;
  }
};

}  // namespace wearscale::tribometer
