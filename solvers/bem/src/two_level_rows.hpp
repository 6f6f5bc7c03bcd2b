#pragma once
// The row operations of the two-level stiffness (TwoLevelStiffness), shared by
// the whole grid and the grid held in slabs (SlabTwoLevelStiffness): each
// works on one row given the rows around it, so a slab passes its halo rows
// where the whole grid wraps around. Private to bem.
#include <cstddef>

namespace wearscale::bem::detail {

/// Full weighting of one line (cell-centred, periodic): (f₋₁ + 3f₀ + 3f₁ + f₂)/8.
inline double full_weighting(double before, double a, double b, double after) {
  return 0.125 * (before + after) + 0.375 * (a + b);
}

/// R along a row: ny values (ny even, ≥ 4) to ny/2, periodic.
inline void restrict_row(const double* f, std::size_t ny, double* out) {
  const std::size_t my = ny / 2;
  out[0] = full_weighting(f[ny - 1], f[0], f[1], f[2]);
#pragma omp simd
  for (std::size_t J = 1; J < my - 1; ++J) out[J] = full_weighting(f[2 * J - 1], f[2 * J], f[2 * J + 1], f[2 * J + 2]);
  out[my - 1] = full_weighting(f[ny - 3], f[ny - 2], f[ny - 1], f[0]);
}

/// R across rows: the coarse row of the fine rows 2I and 2I+1 (a, b) from
/// them and the rows just outside the pair (before, after), my values each.
inline void restrict_rows(const double* before, const double* a, const double* b, const double* after,
                          std::size_t my, double* out) {
#pragma omp simd
  for (std::size_t J = 0; J < my; ++J) out[J] = full_weighting(before[J], a[J], b[J], after[J]);
}

/// P along a row (bilinear, = 2 Rᵀ): my coarse values to 2 my, periodic:
/// fine 2J gets (c[J−1] + 3c[J])/4, fine 2J+1 gets (3c[J] + c[J+1])/4.
inline void prolong_row(const double* c, std::size_t my, double* out) {
  for (std::size_t J = 0; J < my; ++J) {
    const double before = c[J == 0 ? my - 1 : J - 1], here = c[J], after = c[J + 1 == my ? 0 : J + 1];
    out[2 * J] = 0.25 * before + 0.75 * here;
    out[2 * J + 1] = 0.75 * here + 0.25 * after;
  }
}

/// The stencil a + b(−Δ_h) and P across rows, fine row i: z = a f + cx (2f −
/// up − down) + cy (2f − f[j−1] − f[j+1]) + (3 near + far)/4, `near` the
/// prolonged coarse row i/2 and `far` its neighbour on i's side (i/2 − 1 for an
/// even i, i/2 + 1 for an odd one), cx = b/dx², cy = b/dy².
inline void stencil_and_prolong_rows(const double* up, const double* f, const double* down, const double* near,
                                     const double* far, std::size_t ny, double a, double cx, double cy, double* z) {
  const double centre = a + 2.0 * (cx + cy);
  z[0] = centre * f[0] - cx * (up[0] + down[0]) - cy * (f[ny - 1] + f[1]) + 0.75 * near[0] + 0.25 * far[0];
#pragma omp simd
  for (std::size_t j = 1; j < ny - 1; ++j)
    z[j] = centre * f[j] - cx * (up[j] + down[j]) - cy * (f[j - 1] + f[j + 1]) + 0.75 * near[j] + 0.25 * far[j];
  z[ny - 1] = centre * f[ny - 1] - cx * (up[ny - 1] + down[ny - 1]) - cy * (f[ny - 2] + f[0]) + 0.75 * near[ny - 1] +
              0.25 * far[ny - 1];
}

}  // namespace wearscale::bem::detail
