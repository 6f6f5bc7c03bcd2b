#pragma once
// SubsurfaceStress on a grid distributed in slabs over the ranks of an MPI
// job: each rank keeps its rows of the traction spectra and transforms its
// rows of the stresses at any depth, with the transforms of the body it was
// solved on (SlabHalfSpace::fft()). The modes are SubsurfaceStress::mode's,
// so the fields are the serial ones to round-off. Collective calls.
#include <complex>
#include <vector>

#include "wearscale/bem/subsurface_stress.hpp"
#include "wearscale/core/slab_fft.hpp"

namespace wearscale::bem {

class SlabSubsurfaceStress {
 public:
  /// InputError unless −1 < ν ≤ 0.5. `fft` transforms `grid` in slabs and must outlive this object.
  SlabSubsurfaceStress(const Grid2D& grid, double poisson, SlabFFT& fft);

  /// This rank's rows of the surface tractions (their spectra are kept for every depth).
  void set_traction(const VectorField& slab);
  /// This rank's rows of σ at depth z ≥ 0 (z = 0: the surface). InputError if z < 0.
  void stress(double depth, StressField& slab);

  const Grid2D& local_grid() const { return local_; }

 private:
  Grid2D grid_, local_;
  double nu_;
  SlabFFT* fft_;
  std::vector<std::complex<double>> px_, py_, pz_;             // this rank's rows of the traction spectra
  std::vector<std::complex<double>> sxx_, syy_, szz_, sxy_, sxz_, syz_;  // of the stress spectra at one depth
};

}  // namespace wearscale::bem
