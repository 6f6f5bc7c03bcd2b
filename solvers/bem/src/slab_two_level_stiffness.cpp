#include "wearscale/bem/slab_two_level_stiffness.hpp"

#include <span>
#include <stdexcept>

#include "two_level_rows.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/core/row_halo.hpp"

namespace wearscale::bem {

namespace {
// The rows `mine` moved to start and end on even rows: [2⌊first/2⌋,
// 2⌊(first + rows)/2⌋). The ranks' ranges tile the rows as FFTW's do (each
// ends where the next begins), so these tile them too, every slab in pairs.
RowRange paired(RowRange mine) {
  if (mine.rows == 0) return {mine.first / 2 * 2, 0};
  const std::size_t first = mine.first / 2 * 2, end = (mine.first + mine.rows) / 2 * 2;
  return {first, end - first};
}

// The first and last of `rows` rows of `length` values (empty spans for none).
std::span<const double> row(const double* rows, std::size_t count, std::size_t k, std::size_t length) {
  return count == 0 ? std::span<const double>() : std::span<const double>(rows + k * length, length);
}
}  // namespace

SlabTwoLevelStiffness::SlabTwoLevelStiffness(const Grid2D& grid, RowRange mine, double e_star, PlanRigor rigor)
    : grid_(grid),
      coarse_grid_(TwoLevelStiffness::supports(grid) ? TwoLevelStiffness::coarse_grid(grid) : grid),
      paired_(paired(mine)),
      coarse_fft_(coarse_grid_.nx, coarse_grid_.ny, rigor) {
  if (!TwoLevelStiffness::supports(grid)) throw std::invalid_argument("SlabTwoLevelStiffness: the grid has no 2× coarser grid");
  if (!(e_star > 0.0)) throw std::invalid_argument("SlabTwoLevelStiffness: E* must be > 0");
  stencil_ = TwoLevelStiffness::stencil(grid, e_star);
  const std::size_t ny = grid.ny, my = coarse_grid_.ny, rows = paired_.rows;
  const bool moved = paired_.first != mine.first || paired_.rows != mine.rows;
  if (mpi::max(moved ? 1.0 : 0.0) > 0.0) {  // collective: every rank takes part in the moves
    to_paired_ = std::make_unique<RowExchange>(mine, paired_, ny);
    r_.assign(rows * ny, 0.0);
    z_.assign(rows * ny, 0.0);
  }
  const RowRange coarse_rows{coarse_fft_.first_row(), coarse_fft_.rows()};
  to_coarse_fft_ = std::make_unique<RowExchange>(RowRange{paired_.first / 2, rows / 2}, coarse_rows, my);
  half_.assign(rows * my, 0.0);  // = rows/2 × ny
  coarse_.assign(rows / 2 * my, 0.0);
  coarse_fft_rows_.assign(coarse_rows.rows * my, 0.0);
  before_.assign(ny, 0.0);
  after_.assign(ny, 0.0);
  coarse_before_.assign(ny, 0.0);
  coarse_after_.assign(ny, 0.0);
  const std::size_t cols = coarse_fft_.spectral_ny();
  correction_.assign(coarse_rows.rows * cols, 0.0);
  for (std::size_t i = 0; i < coarse_rows.rows; ++i)
    for (std::size_t j = 0; j < cols; ++j)
      correction_[i * cols + j] =
          TwoLevelStiffness::correction_mode(coarse_grid_, coarse_rows.first + i, j, stencil_, e_star);
}

SlabTwoLevelStiffness::~SlabTwoLevelStiffness() = default;

// TwoLevelStiffness::apply, its wrap-arounds replaced by the rows just outside
// this rank's pairs of rows.
void SlabTwoLevelStiffness::apply(const double* r, double* z) {
  const std::size_t ny = grid_.ny, my = coarse_grid_.ny, rows = paired_.rows, pairs = rows / 2;
  const double* f = r;
  double* out = z;
  if (to_paired_) {
    to_paired_->forward(r, r_.data());
    f = r_.data();
    out = z_.data();
  }
  double* h = half_.data();
  double* c = coarse_.data();
  // R: along the rows, then across the pairs of rows with the restricted rows outside them.
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < rows; ++i) detail::restrict_row(f + i * ny, ny, h + i * my);
  const std::span<double> before(before_.data(), my), after(after_.data(), my);
  exchange_row_halo(paired_, row(h, rows, 0, my), row(h, rows, rows - 1, my), before, after);
#pragma omp parallel for schedule(static)
  for (std::size_t I = 0; I < pairs; ++I)
    detail::restrict_rows(I == 0 ? before.data() : h + (2 * I - 1) * my, h + 2 * I * my, h + (2 * I + 1) * my,
                          I + 1 == pairs ? after.data() : h + (2 * I + 2) * my, my, c + I * my);
  // C on the coarse grid's own slabs.
  to_coarse_fft_->forward(c, coarse_fft_rows_.data());
  coarse_fft_.load(coarse_fft_rows_.data());
  coarse_fft_.forward();
  multiply_modes({coarse_fft_.spectrum(), correction_.size()}, correction_);
  coarse_fft_.backward();
  coarse_fft_.store(coarse_fft_rows_.data());
  to_coarse_fft_->backward(coarse_fft_rows_.data(), c);
  // P along the coarse rows, then across them with the stencil; the rows outside from the neighbours.
#pragma omp parallel for schedule(static)
  for (std::size_t I = 0; I < pairs; ++I) detail::prolong_row(c + I * my, my, h + I * ny);
  exchange_row_halo({paired_.first / 2, pairs}, row(h, pairs, 0, ny), row(h, pairs, pairs - 1, ny), coarse_before_,
                    coarse_after_);
  exchange_row_halo(paired_, row(f, rows, 0, ny), row(f, rows, rows - 1, ny), before_, after_);
  const TwoLevelStiffness::Stencil st = stencil_;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < rows; ++i) {
    const std::size_t I = i / 2;
    const double* far = i % 2 == 0 ? (I == 0 ? coarse_before_.data() : h + (I - 1) * ny)
                                   : (I + 1 == pairs ? coarse_after_.data() : h + (I + 1) * ny);
    detail::stencil_and_prolong_rows(i == 0 ? before_.data() : f + (i - 1) * ny, f + i * ny,
                                     i + 1 == rows ? after_.data() : f + (i + 1) * ny, h + I * ny, far, ny, st.a,
                                     st.cx, st.cy, out + i * ny);
  }
  if (to_paired_) to_paired_->backward(z_.data(), z);
}

}  // namespace wearscale::bem
