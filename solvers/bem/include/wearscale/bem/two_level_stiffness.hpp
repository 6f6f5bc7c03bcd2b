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
// rough case of docs/bem.md, keeps the iterations of S itself. Periodic grids
// with an even number of points ≥ 4 each way (supports()). The same operator
// on a grid held in slabs: SlabTwoLevelStiffness.
#include <memory>
#include <vector>

#include "wearscale/core/fft.hpp"
#include "wearscale/core/field.hpp"

namespace wearscale::bem {

class TwoLevelStiffness {
 public:
  /// The stencil's coefficients: a [Pa/m], b [Pa·m], and cx = b/dx², cy = b/dy².
  struct Stencil {
    double a, b, cx, cy;
  };
  /// Whether the grid has a 2× coarser grid (nx, ny even and ≥ 4).
  static bool supports(const Grid2D& grid);
  static Stencil stencil(const Grid2D& grid, double e_star);
  /// The 2× coarser grid of `grid` (the same size).
  static Grid2D coarse_grid(const Grid2D& grid);
  /// C at r2c mode (i, j) of the coarse grid, 1/N_coarse folded in: Ŝ − (a + b q²), 0 at q = 0.
  static double correction_mode(const Grid2D& coarse, std::size_t i, std::size_t j, const Stencil& s, double e_star);

  /// std::invalid_argument unless supports(grid) and E* > 0.
  TwoLevelStiffness(const Grid2D& grid, double e_star);

  /// z = M r on the grid (z may not alias r). Allocates nothing.
  void apply(const RealField& r, RealField& z);

 private:
  Grid2D grid_, coarse_grid_;
  Stencil stencil_;
  std::shared_ptr<const FFTPlan> plan_;
  std::vector<double> correction_;  // C on the coarse grid's r2c modes
  std::vector<double> half_;        // R or P along rows alone: nx × ny/2 (restriction), nx/2 × ny (prolongation)
  RealField coarse_;
  ComplexField spectrum_;
};

}  // namespace wearscale::bem
