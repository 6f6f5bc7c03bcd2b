#pragma once
// The x → x block of the Boussinesq–Cerruti operator of a half-space: the
// surface displacement u_x caused by a tangential traction p_x (4.3)–(4.5),
// the only block the energy release of a sheared contact needs (§4.1: the
// normal load does not change ΔE_el, (4.19)–(4.23)).
//
// The micro-contact map is a window of L × L on an unbounded half-space
// (non-periodic): the x → x block of bem::HalfSpace with a free boundary,
// Cerruti's (4.3) integrated exactly over a cell, u = G * p a linear
// convolution by FFT on a zero-padded 2n × 2n grid. (A periodic operator has
// no zero mode for the mean shear, its kernel has zero mean, and unloading a
// region could raise the energy; (5.3) needs u' < u everywhere, which the
// positive kernel gives.) The kernel is also kept in real space for the
// sums over small regions.
#include <vector>

#include "wearscale/bem/half_space.hpp"

namespace wearscale::wear {

class TangentialCompliance {
 public:
  /// Scratch of the padded grid for one solve (one per thread).
  using Workspace = bem::HalfSpace::Workspace;

  /// InputError unless G > 0, −1 < ν ≤ 0.5 and the grid has square cells.
  TangentialCompliance(const Grid2D& grid, double shear_modulus, double poisson);

  const Grid2D& grid() const { return body_.grid(); }
  double shear_modulus() const { return body_.shear_modulus(); }
  double poisson() const { return body_.poisson(); }
  Workspace workspace() const { return body_.workspace(); }

  /// u_x = G * p_x on the window (one r2c and one c2r of the padded grid).
  /// Threads may call this concurrently, each with its own workspace.
  void displacement(const RealField& traction, RealField& u, Workspace& w) const {
    body_.shear_displacement(traction, u, w);
  }

  /// G(di, dj): u_x at cell offset (di, dj) per unit p_x on one cell [m/Pa]:
  /// (4.3) integrated over the cell, (1/4πG) Σ_corners ± [2(1−ν) x asinh(y/|x|) + 2 y asinh(x/|y|)].
  double kernel(long di, long dj) const { return kernel_row(di)[dj]; }

  /// Row di of the kernel, centred: row[dj] = G(di, dj) for |dj| < ny, and 0
  /// for ny ≤ dj < padded_ny() (so that sums over blocks of 8 cells may run
  /// past the last one).
  const double* kernel_row(long di) const {
    return table_.data() + static_cast<std::size_t>(di < 0 ? -di : di) * 2 * padded_ny_ + padded_ny_;
  }
  /// ny rounded up to a multiple of 8.
  std::size_t padded_ny() const { return padded_ny_; }
  /// Row a = 0 … nx of the kernel summed along x, laid out as kernel_row():
  /// row[dj] = Σ_{0 ≤ a' < a} G(a', dj), so that a run of cells along x sums
  /// as the difference of two rows (summed in extended precision, rounded once).
  const double* cumulative_row(std::size_t a) const {
    return cumulative_.data() + a * 2 * padded_ny_ + padded_ny_;
  }

  /// The cell-integrated kernel at any offset (in cells), for checks.
  static double cell_kernel(double di, double dj, double cell, double shear_modulus, double poisson) {
    return bem::HalfSpace::cell_response(bem::Block::xx, di, dj, cell, cell, shear_modulus, poisson);
  }

  /// E_el = ½ ΔA Σ p_x u_x   (4.2)
  double energy(const RealField& traction, const RealField& u) const;

 private:
  bem::HalfSpace body_;        // free boundary, x → x block
  std::size_t padded_ny_ = 0;
  std::vector<double> table_;  // nx rows of 2 padded_ny: G(|di|, dj) at [|di| 2 padded_ny + padded_ny + dj]
  std::vector<double> cumulative_;  // nx + 1 rows alike: Σ_{a' < a} G(a', dj)
};

}  // namespace wearscale::wear
