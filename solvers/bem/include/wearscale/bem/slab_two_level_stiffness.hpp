#pragma once
// TwoLevelStiffness on a periodic grid held in slabs of rows over the ranks of
// an MPI job: the same operator, row for row the same arithmetic (the row
// operations are shared), its coarse grid on an FFTW-MPI transform of its own.
// The restriction pairs rows 2I and 2I+1, so the rows are first moved to slabs
// that start on even rows (when FFTW's do not); the rows just outside a slab
// come from its neighbours. Every call is collective.
#include <memory>
#include <vector>

#include "wearscale/bem/two_level_stiffness.hpp"
#include "wearscale/core/row_exchange.hpp"
#include "wearscale/core/slab_fft.hpp"

namespace wearscale::bem {

class SlabTwoLevelStiffness {
 public:
  /// This rank holds rows `mine` of `grid` (the ranks' rows tile it in rank
  /// order). std::invalid_argument unless TwoLevelStiffness::supports(grid)
  /// and E* > 0. Collective.
  SlabTwoLevelStiffness(const Grid2D& grid, RowRange mine, double e_star, PlanRigor rigor);
  ~SlabTwoLevelStiffness();
  SlabTwoLevelStiffness(const SlabTwoLevelStiffness&) = delete;
  SlabTwoLevelStiffness& operator=(const SlabTwoLevelStiffness&) = delete;

  /// z = M r on this rank's rows (mine.rows × ny values each). Collective; allocates nothing.
  void apply(const double* r, double* z);

 private:
  Grid2D grid_, coarse_grid_;
  TwoLevelStiffness::Stencil stencil_;
  RowRange paired_;                            // this rank's rows moved to start on an even row
  std::unique_ptr<RowExchange> to_paired_;     // null when every rank's rows already start even
  std::unique_ptr<RowExchange> to_coarse_fft_;  // coarse rows I = paired/2 → the coarse transform's rows
  SlabFFT coarse_fft_;
  std::vector<double> correction_;  // C on this rank's rows of the coarse r2c modes
  std::vector<double> r_, z_;       // the paired rows of r and z (when moved)
  std::vector<double> half_;        // R or P along rows: paired.rows × ny/2 and paired.rows/2 × ny
  std::vector<double> coarse_, coarse_fft_rows_;  // paired.rows/2 × ny/2; the transform's rows × ny/2
  std::vector<double> before_, after_;            // halo rows (up to ny values)
  std::vector<double> coarse_before_, coarse_after_;
};

}  // namespace wearscale::bem
