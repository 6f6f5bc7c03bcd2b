#include "wearscale/bem/slab_free_half_space.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "wearscale/bem/slab_half_space.hpp"
#include "wearscale/bem/spectral_modes.hpp"
#include "wearscale/core/mpi.hpp"

namespace wearscale::bem {

namespace {
// The offset, in cells, that padded index i of 2n stands for: i below n, i − 2n
// above it (its magnitude returned); n itself stands for none (−1): the
// kernel's placement on the padded grid (HalfSpace's free kernel).
long padded_offset(std::size_t i, std::size_t n) {
  if (i < n) return static_cast<long>(i);
  if (i == n) return -1;
  return static_cast<long>(2 * n - i);
}
}  // namespace

SlabFreeHalfSpace::SlabFreeHalfSpace(const Grid2D& grid, double e_star, PlanRigor rigor)
    : grid_(checked_slab_grid(grid, e_star, "distributed free half-space")), padded_(2 * grid.nx, 2 * grid.ny, 2 * grid.lx, 2 * grid.ly),
      rows_(SlabFFT::layout(grid.nx, grid.ny)), fft_(padded_.nx, padded_.ny, rigor),
      held_{fft_.first_row(), fft_.first_row() < grid.nx ? std::min(fft_.rows(), grid.nx - fft_.first_row()) : 0},
      exchange_(rows_, held_, grid.ny) {
  local_ = grid_.slab(rows_.rows);
  staging_.assign(held_.rows * grid_.ny, 0.0);
  const Grid2D slab = padded_.slab(fft_.rows());
  const std::size_t first = fft_.first_row(), pad = fft_.padded_ny(), nx = grid_.nx, ny = grid_.ny;
  // Love's cell response at each offset, placed as the serial free kernel places it, then one r2c.
  const double dx = grid_.dx(), dy = grid_.dy(), shear = 0.5 * e_star;  // HalfSpace::normal: E = E*, ν = 0
  double* real = fft_.real();
#pragma omp parallel for schedule(dynamic, 16)
  for (std::size_t i = 0; i < fft_.rows(); ++i) {
    const long a = padded_offset(first + i, nx);
    for (std::size_t j = 0; j < pad; ++j) {
      const long b = j < padded_.ny ? padded_offset(j, ny) : -1;
      real[i * pad + j] = a < 0 || b < 0 ? 0.0
                                         : HalfSpace::cell_response(Block::zz, static_cast<double>(a),
                                                                    static_cast<double>(b), dx, dy, shear, 0.0);
    }
  }
  fft_.forward();
  const std::size_t modes = fft_.rows() * padded_.spectral_ny();
  const double inv_n = 1.0 / static_cast<double>(padded_.size());
  zz_.assign(modes, 0.0);
  stiffness_.assign(modes, 0.0);
  const auto* s = fft_.spectrum();
  for_each_mode(slab, [&](std::size_t i, std::size_t j, std::size_t m) {
    zz_[m] = s[m].real() * inv_n;  // the kernel is even in x and y: its spectrum is real
    stiffness_[m] = HalfSpace::stiffness_mode(padded_, first + i, j, e_star);
  });
  self_compliance_ = whole_spectrum_sum(zz_);
  stiffness_diagonal_ = whole_spectrum_sum(stiffness_);
}

double SlabFreeHalfSpace::whole_spectrum_sum(const std::vector<double>& kernel) const {
  const double s = hermitian_sum<double>(padded_.slab(fft_.rows()),
                                         [&](std::size_t m, double w, double& t) { t += w * kernel[m]; });
  return mpi::sum(s);
}

void SlabFreeHalfSpace::load(const RealField& in) {
  if (!(in.grid() == local_)) throw std::invalid_argument("SlabFreeHalfSpace: a field that is not this rank's slab");
  exchange_.forward(in.data(), staging_.data());
  const std::size_t rows = fft_.rows(), held = held_.rows, pad = fft_.padded_ny(), ny = grid_.ny;
  const double* from = staging_.data();
  double* real = fft_.real();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < rows; ++i) {
    double* row = real + i * pad;
    const std::size_t copied = i < held ? ny : 0;
    if (copied > 0) std::memcpy(row, from + i * ny, ny * sizeof(double));
    std::fill(row + copied, row + pad, 0.0);
  }
}

void SlabFreeHalfSpace::store(RealField& out) {
  if (!(out.grid() == local_)) throw std::invalid_argument("SlabFreeHalfSpace: a field that is not this rank's slab");
  const std::size_t held = held_.rows, pad = fft_.padded_ny(), ny = grid_.ny;
  const double* real = fft_.real();
  double* to = staging_.data();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < held; ++i) std::memcpy(to + i * ny, real + i * pad, ny * sizeof(double));
  exchange_.backward(staging_.data(), out.data());
}

void SlabFreeHalfSpace::apply(const RealField& in, RealField& out, const std::vector<double>& kernel, double scale) {
  load(in);
  fft_.forward();
  multiply_modes({fft_.spectrum(), kernel.size()}, kernel, scale);
  fft_.backward();
  store(out);
}

void SlabFreeHalfSpace::displacement(const RealField& p, RealField& u, double scale) { apply(p, u, zz_, scale); }
void SlabFreeHalfSpace::stiffness(const RealField& g, RealField& z) { apply(g, z, stiffness_, 1.0); }

double SlabFreeHalfSpace::form(const RealField& t) {
  load(t);
  fft_.forward();
  const auto* s = fft_.spectrum();
  const double* k = zz_.data();
  // Σ_x t (F t) over the padded grid, where t is zero outside the contact's
  // rows: (1/N) Σ_q F(q) |t̂(q)|², the 1/N being in the kernel.
  const double local = hermitian_sum<double>(
      padded_.slab(fft_.rows()), [&](std::size_t m, double w, double& sum) { sum += w * k[m] * std::norm(s[m]); });
  return mpi::sum(local);
}

void SlabFreeHalfSpace::sum(std::span<double> partial) const { mpi::sum(partial); }
double SlabFreeHalfSpace::max(double local) const { return mpi::max(local); }

}  // namespace wearscale::bem
