#pragma once
// A cheap approximation of the periodic half-space's stiffness S (Ŝ(q) =
// E*|q|/2, the inverse of the normal block): the preconditioner of the normal
// contact solver at about a quarter of the transforms of S itself.
//
//   M r = a r + b (−Δ_h r) + P C R r,
//
// a + b(−Δ_h) a five-point stencil on the grid (its symbol a + b q² fits |q|
// over the finest band), R full weighting onto the 2× coarser grid, P = 4 Rᵀ
// bilinear prolongation, and C the coarse grid's Ŝ − (a + b q²) by one FFT
// pair of a quarter of the points. M is symmetric (P = 4 Rᵀ) and, on the
// issue's rough case, keeps the iterations of S itself (docs/bem.md).
// Periodic grids with an even number of points ≥ 4 each way (supports()).
#include <memory>
#include <vector>

#include "wearscale/core/fft.hpp"
#include "wearscale/core/field.hpp"

namespace wearscale::bem {

class TwoLevelStiffness {
 public:
  /// Whether the grid has a 2× coarser grid (nx, ny even and ≥ 4).
  static bool supports(const Grid2D& grid);
  /// std::invalid_argument unless supports(grid) and E* > 0.
  TwoLevelStiffness(const Grid2D& grid, double e_star);

  /// z = M r on the grid (z may not alias r). Allocates nothing.
  void apply(const RealField& r, RealField& z);

  /// The stencil's coefficients: a [Pa/m], b [Pa·m].
  double a() const { return a_; }
  double b() const { return b_; }

 private:
  void restrict_to_coarse(const RealField& r);            // coarse_ = R r
  void prolong_and_add(const RealField& r, RealField& z);  // z = a r + b(−Δ_h r) + P coarse_

  Grid2D grid_, coarse_grid_;
  double a_, b_, cx_, cy_;  // cx = b/dx², cy = b/dy²
  std::shared_ptr<const FFTPlan> plan_;
  std::vector<double> correction_;  // Ŝ − (a + b q²) on the coarse modes, 1/N_coarse folded in
  std::vector<double> half_;        // R or P in y alone: nx × ny/2 (restriction), nx/2 × ny (prolongation)
  RealField coarse_;
  ComplexField spectrum_;
};

}  // namespace wearscale::bem
