#pragma once
// What the frictional contact solver asks of the elastic body, on the points
// this process holds: the normal operator's (NormalOperator: the rows held,
// sums and max over all points) and the whole Boussinesq–Cerruti tensor, u = F p
// for all three components and the blocks of Σ t·(F t). One process holds the
// whole grid (HalfSpaceTraction, the serial body) or one slab of rows of it
// (SlabHalfSpace from E and ν, distributed over MPI ranks with FFTW-MPI):
// FrictionalContact is one solver over either, as NormalContact is.
#include "wearscale/bem/half_space.hpp"
#include "wearscale/bem/normal_operator.hpp"

namespace wearscale::bem {

class TractionOperator : public NormalOperator {
 public:
  virtual double young() const = 0;
  virtual double poisson() const = 0;
  /// u = F * p, all three components, on the rows held here.
  virtual void vector_displacement(const VectorField& p, VectorField& u) = 0;
  /// The blocks of Σ over every point of the grid of t·(F t) (nn, tt, nt).
  virtual HalfSpace::BlockForm block_form(const VectorField& t) = 0;
};

/// The serial body: a whole-grid periodic HalfSpace with every block.
class HalfSpaceTraction final : public WholeGridBody<TractionOperator> {
 public:
  HalfSpaceTraction(const Grid2D& grid, double young, double poisson)
      : WholeGridBody(HalfSpace(grid, young, poisson, Boundary::Periodic, Response::Full)) {}

  double young() const override { return body_.young(); }
  double poisson() const override { return body_.poisson(); }
  void vector_displacement(const VectorField& p, VectorField& u) override { body_.displacement(p, u, work_); }
  HalfSpace::BlockForm block_form(const VectorField& t) override { return body_.form(t, work_); }
};

}  // namespace wearscale::bem
