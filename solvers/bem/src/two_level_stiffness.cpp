#include "wearscale/bem/two_level_stiffness.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "two_level_rows.hpp"

namespace wearscale::bem {

namespace {
// The stencil's fit to Ŝ = E*|q|/2 (q_max = π√(1/dx² + 1/dy²), the lattice's
// corner): a = 0.1 Ŝ(q_max), b = E*/q_max. Chosen on the rough case of
// docs/bem.md (bench/bem/local_preconditioners.py, fw0.05:1): 33, 38, 45, 53,
// 56 iterations at 256² to 4096² against S's own 31, 36, 44, 55, 61; at 1024²
// a doubled 47, a × 4 or b × 1.5 50.
constexpr double kA = 0.1, kB = 1.0;
}  // namespace

bool TwoLevelStiffness::supports(const Grid2D& g) {
  return g.nx >= 4 && g.ny >= 4 && g.nx % 2 == 0 && g.ny % 2 == 0;
}

TwoLevelStiffness::Stencil TwoLevelStiffness::stencil(const Grid2D& g, double e_star) {
  const double dx = g.dx(), dy = g.dy();
  const double q_max = std::numbers::pi * std::sqrt(1.0 / (dx * dx) + 1.0 / (dy * dy));
  const double b = kB * e_star / q_max;
  return {kA * 0.5 * e_star * q_max, b, b / (dx * dx), b / (dy * dy)};
}

Grid2D TwoLevelStiffness::coarse_grid(const Grid2D& g) { return Grid2D(g.nx / 2, g.ny / 2, g.lx, g.ly); }

double TwoLevelStiffness::correction_mode(const Grid2D& coarse, std::size_t i, std::size_t j, const Stencil& s,
                                          double e_star) {
  const double qx = coarse.wavenumber_x(i), qy = coarse.wavenumber_y(j), q2 = qx * qx + qy * qy;
  if (!(q2 > 0.0)) return 0.0;
  return (0.5 * e_star * std::sqrt(q2) - (s.a + s.b * q2)) / static_cast<double>(coarse.size());
}

TwoLevelStiffness::TwoLevelStiffness(const Grid2D& grid, double e_star)
    : grid_(grid), coarse_grid_(coarse_grid(grid)) {
  if (!supports(grid)) throw std::invalid_argument("TwoLevelStiffness: the grid has no 2× coarser grid");
  if (!(e_star > 0.0)) throw std::invalid_argument("TwoLevelStiffness: E* must be > 0");
  stencil_ = stencil(grid, e_star);
  plan_ = FFTPlanCache::global().plan(coarse_grid_);
  coarse_ = RealField(coarse_grid_);
  spectrum_ = ComplexField::spectrum_of(coarse_grid_);
  half_.assign(grid.nx * coarse_grid_.ny, 0.0);
  const std::size_t cols = coarse_grid_.spectral_ny();
  correction_.assign(coarse_grid_.spectral_size(), 0.0);
  for (std::size_t i = 0; i < coarse_grid_.nx; ++i)
    for (std::size_t j = 0; j < cols; ++j) correction_[i * cols + j] = correction_mode(coarse_grid_, i, j, stencil_, e_star);
}

void TwoLevelStiffness::apply(const RealField& r, RealField& z) {
  if (!(r.grid() == grid_) || !(z.grid() == grid_))
    throw std::invalid_argument("TwoLevelStiffness::apply: a field on another grid");
  const std::size_t nx = grid_.nx, ny = grid_.ny, mx = coarse_grid_.nx, my = coarse_grid_.ny;
  const double* f = r.data();
  double* h = half_.data();
  double* c = coarse_.data();
  // R: along the rows into half_ (nx × my), then across them into coarse_.
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < nx; ++i) detail::restrict_row(f + i * ny, ny, h + i * my);
#pragma omp parallel for schedule(static)
  for (std::size_t I = 0; I < mx; ++I)
    detail::restrict_rows(h + ((2 * I + nx - 1) % nx) * my, h + 2 * I * my, h + (2 * I + 1) * my,
                          h + ((2 * I + 2) % nx) * my, my, c + I * my);
  // C on the coarse grid.
  plan_->forward(coarse_, spectrum_);
  multiply_modes(spectrum_.values(), correction_);
  plan_->backward_unnormalized(spectrum_, coarse_);
  // P along the rows into half_ (mx × ny), then across them with the stencil into z.
#pragma omp parallel for schedule(static)
  for (std::size_t I = 0; I < mx; ++I) detail::prolong_row(c + I * my, my, h + I * ny);
  double* out = z.data();
  const Stencil st = stencil_;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < nx; ++i) {
    const std::size_t I = i / 2, other = i % 2 == 0 ? (I + mx - 1) % mx : (I + 1) % mx;
    detail::stencil_and_prolong_rows(f + ((i + nx - 1) % nx) * ny, f + i * ny, f + ((i + 1) % nx) * ny, h + I * ny,
                                     h + other * ny, ny, st.a, st.cx, st.cy, out + i * ny);
  }
}

}  // namespace wearscale::bem
