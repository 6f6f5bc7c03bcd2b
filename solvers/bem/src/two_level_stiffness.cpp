#include "wearscale/bem/two_level_stiffness.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace wearscale::bem {

namespace {
// The stencil's fit to Ŝ = E*|q|/2 (q_max = π√(1/dx² + 1/dy²), the lattice's
// corner): a = 0.1 Ŝ(q_max), b = E*/q_max. Chosen on the rough case of #22
// (numpy prototype, bench/bem/local_preconditioners.py's surface): 33, 38, 45,
// 53 iterations at 256² to 2048² against S's own 31, 36, 44, 55; a = 0.2 Ŝ,
// or b halved or doubled, cost 2–15 more at 1024².
constexpr double kA = 0.1, kB = 1.0;

// Full weighting of one line (cell-centred, periodic): out[I] = (in[2I−1] +
// 3 in[2I] + 3 in[2I+1] + in[2I+2]) / 8, n = 2m values in, m out, stride s.
inline double weighted(double before, double a, double b, double after) {
  return 0.125 * (before + after) + 0.375 * (a + b);
}
}  // namespace

bool TwoLevelStiffness::supports(const Grid2D& g) {
  return g.nx >= 4 && g.ny >= 4 && g.nx % 2 == 0 && g.ny % 2 == 0;
}

TwoLevelStiffness::TwoLevelStiffness(const Grid2D& grid, double e_star)
    : grid_(grid), coarse_grid_(grid.nx / 2, grid.ny / 2, grid.lx, grid.ly) {
  if (!supports(grid)) throw std::invalid_argument("TwoLevelStiffness: the grid has no 2× coarser grid");
  if (!(e_star > 0.0)) throw std::invalid_argument("TwoLevelStiffness: E* must be > 0");
  const double dx = grid.dx(), dy = grid.dy();
  const double q_max = std::numbers::pi * std::sqrt(1.0 / (dx * dx) + 1.0 / (dy * dy));
  a_ = kA * 0.5 * e_star * q_max;
  b_ = kB * e_star / q_max;
  cx_ = b_ / (dx * dx);
  cy_ = b_ / (dy * dy);
  plan_ = FFTPlanCache::global().plan(coarse_grid_);
  coarse_ = RealField(coarse_grid_);
  spectrum_ = ComplexField::spectrum_of(coarse_grid_);
  half_.assign(grid.nx * coarse_grid_.ny, 0.0);
  const std::size_t cols = coarse_grid_.spectral_ny();
  const double scale = 1.0 / static_cast<double>(coarse_grid_.size());  // the unnormalised backward's 1/N
  correction_.assign(coarse_grid_.spectral_size(), 0.0);
  for (std::size_t i = 0; i < coarse_grid_.nx; ++i)
    for (std::size_t j = 0; j < cols; ++j) {
      const double qx = coarse_grid_.wavenumber_x(i), qy = coarse_grid_.wavenumber_y(j), q2 = qx * qx + qy * qy;
      correction_[i * cols + j] = q2 > 0.0 ? scale * (0.5 * e_star * std::sqrt(q2) - (a_ + b_ * q2)) : 0.0;
    }
}

// R in y row by row into half_ (nx × my), then in x into coarse_ (mx × my).
void TwoLevelStiffness::restrict_to_coarse(const RealField& r) {
  const std::size_t nx = grid_.nx, ny = grid_.ny, mx = coarse_grid_.nx, my = coarse_grid_.ny;
  const double* in = r.data();
  double* h = half_.data();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < nx; ++i) {
    const double* f = in + i * ny;
    double* o = h + i * my;
    o[0] = weighted(f[ny - 1], f[0], f[1], f[2]);
#pragma omp simd
    for (std::size_t J = 1; J < my - 1; ++J) o[J] = weighted(f[2 * J - 1], f[2 * J], f[2 * J + 1], f[2 * J + 2]);
    o[my - 1] = weighted(f[ny - 3], f[ny - 2], f[ny - 1], f[0]);
  }
  double* c = coarse_.data();
#pragma omp parallel for schedule(static)
  for (std::size_t I = 0; I < mx; ++I) {
    const double* before = h + ((2 * I + nx - 1) % nx) * my;
    const double* a = h + (2 * I) * my;
    const double* b = h + (2 * I + 1) * my;
    const double* after = h + ((2 * I + 2) % nx) * my;
    double* o = c + I * my;
#pragma omp simd
    for (std::size_t J = 0; J < my; ++J) o[J] = weighted(before[J], a[J], b[J], after[J]);
  }
}

// P in y into half_ (mx × ny): fine 2J gets (c[J−1] + 3c[J])/4, 2J+1 gets
// (3c[J] + c[J+1])/4; then, fused with the stencil, in x row by row into z.
void TwoLevelStiffness::prolong_and_add(const RealField& r, RealField& z) {
  const std::size_t nx = grid_.nx, ny = grid_.ny, mx = coarse_grid_.nx, my = coarse_grid_.ny;
  const double* c = coarse_.data();
  double* h = half_.data();
#pragma omp parallel for schedule(static)
  for (std::size_t I = 0; I < mx; ++I) {
    const double* row = c + I * my;
    double* o = h + I * ny;
    for (std::size_t J = 0; J < my; ++J) {
      const double before = row[(J + my - 1) % my], here = row[J], after = row[(J + 1) % my];
      o[2 * J] = 0.25 * before + 0.75 * here;
      o[2 * J + 1] = 0.75 * here + 0.25 * after;
    }
  }
  const double a = a_, cx = cx_, cy = cy_, centre = a + 2.0 * (cx + cy);
  const double* in = r.data();
  double* out = z.data();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < nx; ++i) {
    const std::size_t I = i / 2, other = i % 2 == 0 ? (I + mx - 1) % mx : (I + 1) % mx;
    const double* near = h + I * ny;   // weight 3/4
    const double* far = h + other * ny;  // weight 1/4
    const double* f = in + i * ny;
    const double* up = in + ((i + nx - 1) % nx) * ny;
    const double* down = in + ((i + 1) % nx) * ny;
    double* o = out + i * ny;
    o[0] = centre * f[0] - cx * (up[0] + down[0]) - cy * (f[ny - 1] + f[1]) + 0.75 * near[0] + 0.25 * far[0];
#pragma omp simd
    for (std::size_t j = 1; j < ny - 1; ++j)
      o[j] = centre * f[j] - cx * (up[j] + down[j]) - cy * (f[j - 1] + f[j + 1]) + 0.75 * near[j] + 0.25 * far[j];
    o[ny - 1] = centre * f[ny - 1] - cx * (up[ny - 1] + down[ny - 1]) - cy * (f[ny - 2] + f[0]) +
                0.75 * near[ny - 1] + 0.25 * far[ny - 1];
  }
}

void TwoLevelStiffness::apply(const RealField& r, RealField& z) {
  if (!(r.grid() == grid_) || !(z.grid() == grid_))
    throw std::invalid_argument("TwoLevelStiffness::apply: a field on another grid");
  restrict_to_coarse(r);
  plan_->forward(coarse_, spectrum_);
  auto* s = spectrum_.data();
  const double* k = correction_.data();
  const std::size_t modes = correction_.size();
#pragma omp parallel for simd schedule(static)
  for (std::size_t m = 0; m < modes; ++m) s[m] *= k[m];
  plan_->backward_unnormalized(spectrum_, coarse_);
  prolong_and_add(r, z);
}

}  // namespace wearscale::bem
