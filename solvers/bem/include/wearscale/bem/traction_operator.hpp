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
class HalfSpaceTraction final : public TractionOperator {
 public:
  HalfSpaceTraction(const Grid2D& grid, double young, double poisson)
      : body_(grid, young, poisson, Boundary::Periodic, Response::Full), work_(body_.workspace()) {}
  const HalfSpace& half_space() const { return body_; }

  const Grid2D& grid() const override { return body_.grid(); }
  std::size_t first_row() const override { return 0; }
  const Grid2D& local_grid() const override { return body_.grid(); }
  Boundary boundary() const override { return body_.boundary(); }
  double young() const override { return body_.young(); }
  double poisson() const override { return body_.poisson(); }
  void displacement(const RealField& p, RealField& u, double scale) override {
    body_.normal_displacement(p, u, work_, scale);
  }
  void stiffness(const RealField& g, RealField& z) override { body_.normal_stiffness(g, z, work_); }
  double form(const RealField& t) override { return body_.normal_form(t, work_); }
  double self_compliance() const override { return body_.self_compliance(); }
  double stiffness_diagonal() const override { return body_.normal_stiffness_diagonal(); }
  void vector_displacement(const VectorField& p, VectorField& u) override { body_.displacement(p, u, work_); }
  HalfSpace::BlockForm block_form(const VectorField& t) override { return body_.form(t, work_); }
  void sum(std::span<double>) const override {}
  double max(double local) const override { return local; }

 private:
  HalfSpace body_;
  HalfSpace::Workspace work_;
};

}  // namespace wearscale::bem
