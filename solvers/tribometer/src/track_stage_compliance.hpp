#pragma once
// Internal to the tribometer library: the compliance of an implicit stage's
// wear on a resolved track.
#include <cmath>
#include <span>
#include <vector>

#include "wearscale/bem/normal_contact.hpp"
#include "wearscale/tribometer/pin_on_disc.hpp"

namespace wearscale::tribometer {

// At the stage's distance s the window reads the strip at the fractional
// offset f = s/Δx − ⌊s/Δx⌋: window row j reads strip cells m_j and m_j + 1
// with weights 1 − f and f (R), and its wear goes back to them with the same
// weights. Over the stage (length γ) a pin cell recedes by w p (w = γ s/p_crit,
// (9.23)-(9.24)) and the disc under the window by Rᵀ R V p (V = γ (1 − s)/p_crit,
// (9.25)): along each window column a tridiagonal operator, diagonal
// c0 v_j with c0 = (1 − f)² + f², next neighbours c1 v_{j±1}, c1 = f (1 − f).
// Its symmetric part V^½ RᵀR V^½ (neighbours c1 √(v_j v_{j±1})) is the
// compliance here; the rest, c1 (v_{j±1} − √(v_j v_{j±1})), nonzero only where
// the material changes along the column, is iterated on in the stage solve.
//
// The preconditioner M = (κ I + A)⁻¹ is exact per column (a tridiagonal
// solve), κ = K(0) the half-space's own compliance of a cell.
struct PinOnDisc::TrackStageCompliance final : bem::AddedCompliance {
  std::vector<double> w, v;  // per window cell [m/Pa]
  std::size_t nx = 0, ny = 0;
  double c0 = 1.0, c1 = 0.0;
  bool wrap = false;         // the strip is as long as the window: row ny − 1 reads row 0's cell
  double kappa = 0.0;
  std::vector<double> readmit;                     // 1/(κ + w + c0 v) per cell
  mutable std::vector<double> sqrt_v, scratch;     // √v; the Thomas algorithm's modified upper diagonal

  void prepare() {
    sqrt_v.resize(v.size());
    readmit.resize(v.size());
    for (std::size_t k = 0; k < v.size(); ++k) {
      sqrt_v[k] = std::sqrt(v[k]);
      readmit[k] = 1.0 / (kappa + w[k] + c0 * v[k]);
    }
    scratch.resize(ny);
  }
  // The neighbour coupling between rows j and j + 1 of column i.
  double coupling(std::size_t i, std::size_t j) const {
    const std::size_t k = i * ny + j, next = i * ny + (j + 1) % ny;
    return c1 * sqrt_v[k] * sqrt_v[next];
  }
  bool links(std::size_t j) const { return j + 1 < ny || wrap; }

  void add(const RealField& p, double scale, RealField& u) const override {
    for (std::size_t i = 0; i < nx; ++i)
      for (std::size_t j = 0; j < ny; ++j) {
        const std::size_t k = i * ny + j;
        double sum = (w[k] + c0 * v[k]) * p[k];
        if (links(j)) sum += coupling(i, j) * p[i * ny + (j + 1) % ny];
        if (j > 0 || wrap) sum += coupling(i, (j + ny - 1) % ny) * p[i * ny + (j + ny - 1) % ny];
        u[k] += scale * sum;
      }
  }
  double quadratic_form(const RealField& t) const override {
    double sum = 0.0;
    for (std::size_t i = 0; i < nx; ++i)
      for (std::size_t j = 0; j < ny; ++j) {
        const std::size_t k = i * ny + j;
        sum += (w[k] + c0 * v[k]) * t[k] * t[k];
        if (links(j)) sum += 2.0 * coupling(i, j) * t[k] * t[i * ny + (j + 1) % ny];
      }
    return sum;
  }
  bool has_preconditioner() const override { return kappa > 0.0; }
  // Per column, the tridiagonal (κ + w + c0 v, c1 √(v v')) solved by the Thomas
  // algorithm (SPD: no pivoting); the wrap-around link, if any, left out.
  void precondition(const RealField& r, RealField& z) const override {
    for (std::size_t i = 0; i < nx; ++i) {
      const double* ri = r.data() + i * ny;
      double* zi = z.data() + i * ny;
      double* cp = scratch.data();
      for (std::size_t j = 0; j < ny; ++j) {
        const std::size_t k = i * ny + j;
        const double diag = kappa + w[k] + c0 * v[k];
        const double lower = j > 0 ? coupling(i, j - 1) : 0.0;
        const double upper = j + 1 < ny ? coupling(i, j) : 0.0;
        const double denom = diag - (j > 0 ? lower * cp[j - 1] : 0.0);
        cp[j] = upper / denom;
        zi[j] = (ri[j] - (j > 0 ? lower * zi[j - 1] : 0.0)) / denom;
      }
      for (std::size_t j = ny - 1; j-- > 0;) zi[j] -= cp[j] * zi[j + 1];
    }
  }
  std::span<const double> precondition_diagonal() const override { return readmit; }
};

}  // namespace wearscale::tribometer
