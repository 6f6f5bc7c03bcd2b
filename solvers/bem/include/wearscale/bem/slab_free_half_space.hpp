#pragma once
// The free half-space's normal block (the window on an unbounded body that
// HalfSpace::normal(g, E*, Boundary::Free) is) distributed in slabs over the
// ranks of an MPI job. The fields are held in the rows FFTW-MPI gives each
// rank of the contact's grid (SlabFFT::layout(nx, ny), so a rough surface
// made in slabs lands on them); the transforms run on the zero-padded
// 2nx × 2ny grid in its own slabs, whose first half holds the contact. Each
// application moves the contact's rows to the ranks holding them in the
// padded slabs and back (RowExchange): every rank keeps its share of both,
// where FFTW's slabs of the padded grid alone would leave the contact on the
// first half of the ranks. The same kernel as the serial body (Love's cell
// response, HalfSpace::cell_response), the same preconditioner on the padded
// grid. Every call is collective.
#include <vector>

#include "wearscale/bem/normal_operator.hpp"
#include "wearscale/core/row_exchange.hpp"
#include "wearscale/core/slab_fft.hpp"

namespace wearscale::bem {

class SlabFreeHalfSpace final : public NormalOperator {
 public:
  /// A rigid surface on an elastic body of contact modulus E* (InputError unless
  /// E* > 0 and the grid has ≥ 2 × 2 points). Collective.
  SlabFreeHalfSpace(const Grid2D& grid, double e_star, PlanRigor rigor = PlanRigor::Measure);

  const Grid2D& grid() const override { return grid_; }
  std::size_t first_row() const override { return rows_.first; }
  std::size_t rows() const { return rows_.rows; }
  const Grid2D& local_grid() const override { return local_; }
  Boundary boundary() const override { return Boundary::Free; }

  void displacement(const RealField& p, RealField& u, double scale) override;
  void stiffness(const RealField& g, RealField& z) override;
  double form(const RealField& t) override;
  double self_compliance() const override { return self_compliance_; }
  double stiffness_diagonal() const override { return stiffness_diagonal_; }
  void sum(std::span<double> partial) const override;
  double max(double local) const override;

 private:
  void load(const RealField& in);                 // the contact's rows into the padded slabs (zeros elsewhere)
  void store(RealField& out);                     // the padded slabs' contact rows back to the contact's rows
  void apply(const RealField& in, RealField& out, const std::vector<double>& kernel, double scale);
  double whole_spectrum_sum(const std::vector<double>& kernel) const;

  Grid2D grid_, padded_, local_;
  RowRange rows_;   // this rank's rows of the contact's grid
  SlabFFT fft_;     // the padded grid's transforms, in its own slabs
  RowRange held_;   // the contact's rows among this rank's padded rows
  RowExchange exchange_;
  std::vector<double> staging_;          // held_.rows × ny: the contact's rows in the padded slab's order
  std::vector<double> zz_, stiffness_;   // this rank's rows of the padded half spectrum, 1/N folded in
  double self_compliance_ = 0.0, stiffness_diagonal_ = 0.0;
};

}  // namespace wearscale::bem
