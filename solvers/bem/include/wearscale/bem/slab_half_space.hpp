#pragma once
// The periodic half-space's normal block distributed in slabs over the ranks
// of an MPI job (FFTW-MPI): each rank holds rows [first_row, first_row + rows)
// of the grid, of the fields and of the kernel's half spectrum, so the memory
// per rank is about 1/P of the serial body's. The same kernel as HalfSpace
// (HalfSpace::normal_mode, stiffness_mode); sums over the ranks add the
// ranks' parts in rank order (mpi::sum), so a solve does not depend on timing.
// Every call is collective: all ranks make the same calls in the same order.
// Built from E and ν it holds the whole Boussinesq–Cerruti tensor
// (HalfSpace::tensor_mode) and serves the frictional solver (TractionOperator).
#include <complex>
#include <memory>
#include <vector>

#include "wearscale/bem/slab_two_level_stiffness.hpp"
#include "wearscale/bem/traction_operator.hpp"
#include "wearscale/core/slab_fft.hpp"

namespace wearscale::bem {

/// The check every body in slabs makes of its grid and modulus: InputError
/// naming `body` unless E* > 0 and the grid has ≥ 2 × 2 points and sizes > 0.
const Grid2D& checked_slab_grid(const Grid2D& grid, double e_star, const char* body);

class SlabHalfSpace final : public TractionOperator {
 public:
  /// A rigid surface on an elastic body of contact modulus E* (InputError unless
  /// E* > 0 and the grid has ≥ 2 × 2 points), periodic. Collective. FFTW's
  /// MEASURE planning times the transforms across the ranks: worth it for long
  /// solves on large grids, not for small ones (Estimate).
  SlabHalfSpace(const Grid2D& grid, double e_star, PlanRigor rigor = PlanRigor::Measure);
  /// Every block of the tensor of an elastic flat of Young's modulus E and
  /// Poisson's ratio ν (InputError unless E > 0 and −1 < ν ≤ 0.5), as a
  /// periodic HalfSpace(grid, E, ν, Periodic, Full) holds them. Collective.
  SlabHalfSpace(const Grid2D& grid, double young, double poisson, PlanRigor rigor);

  const Grid2D& grid() const override { return grid_; }
  std::size_t first_row() const override { return fft_.first_row(); }
  std::size_t rows() const { return fft_.rows(); }
  const Grid2D& local_grid() const override { return local_; }
  Boundary boundary() const override { return Boundary::Periodic; }

  void displacement(const RealField& p, RealField& u, double scale) override;
  void stiffness(const RealField& g, RealField& z) override;
  /// SlabTwoLevelStiffness (made at the first call, collectively); S itself on an odd grid.
  void two_level_stiffness(const RealField& g, RealField& z) override;
  double form(const RealField& t) override;
  double self_compliance() const override { return self_compliance_; }
  double stiffness_diagonal() const override { return stiffness_diagonal_; }
  void sum(std::span<double> partial) const override;
  double max(double local) const override;
  /// The full tensor (the E, ν constructor; std::logic_error otherwise).
  double young() const override { return young_; }
  double poisson() const override { return poisson_; }
  void vector_displacement(const VectorField& p, VectorField& u) override;
  HalfSpace::BlockForm block_form(const VectorField& t) override;

  /// The transforms (for the slab's roughness and generated surfaces).
  SlabFFT& fft() { return fft_; }

 private:
  void apply(const RealField& in, RealField& out, const std::vector<double>& kernel, double scale);
  double whole_spectrum_sum(const std::vector<double>& kernel) const;
  void spectra_of(const VectorField& t);  // the three components' spectra into sx_, sy_, sz_

  Grid2D grid_, local_;
  SlabFFT fft_;
  std::vector<double> zz_, stiffness_;  // this rank's rows of the half spectrum, 1/N folded in
  double self_compliance_ = 0.0, stiffness_diagonal_ = 0.0;
  double young_ = 0.0, poisson_ = 0.0, e_star_ = 0.0;
  PlanRigor rigor_;
  std::unique_ptr<SlabTwoLevelStiffness> two_level_;
  std::vector<HalfSpace::TensorMode> tensor_;     // the full tensor's modes (E, ν constructor), 1/N folded in
  std::vector<std::complex<double>> sx_, sy_, sz_;  // the three components' spectra of one application
};

}  // namespace wearscale::bem
