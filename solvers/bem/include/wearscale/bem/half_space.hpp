#pragma once
// The periodic elastic half-space: surface tractions → surface displacements
// through the Boussinesq–Cerruti Green's tensor in Fourier space (§2.3.1).
//
// Conventions: z points into the solid; p_z > 0 is compressive and u_z > 0
// moves the surface into the solid. The forward FFT is e^{-iq·x}; with the
// unnormalised DFT p̂, û(q) = F(q) p̂(q) and u = IDFT(û) is the periodic
// convolution u = ∫ F(x−x') p(x') dx' (A.4). The zero mode F(0) is set to 0:
// a mean traction gives no mean displacement (in a periodic half-space the
// mean displacement is undefined; contact solvers fix it by their constraint).
#include <array>
#include <complex>

#include "wearscale/core/fft.hpp"

namespace wearscale::bem {

/// Three components of a surface traction or displacement field.
struct VectorField {
  RealField x, y, z;
  explicit VectorField(const Grid2D& g) : x(g), y(g), z(g) {}
  const Grid2D& grid() const { return z.grid(); }
};

using GreenTensor = std::array<std::array<std::complex<double>, 3>, 3>;

class HalfSpace {
 public:
  /// InputError unless E > 0 and −1 < ν ≤ 0.5 (ν = 0.5: incompressible, normal and tangential decoupled).
  HalfSpace(const Grid2D& grid, double young, double poisson);

  const Grid2D& grid() const { return grid_; }
  double young() const { return young_; }
  double poisson() const { return poisson_; }
  double shear_modulus() const { return young_ / (2.0 * (1.0 + poisson_)); }
  /// E/(1−ν²): the E* of this body against a rigid one (1.12).
  double contact_modulus() const { return young_ / (1.0 - poisson_ * poisson_); }

  /// F_ij(q): û_i = F_ij p̂_j, from (2.35), (4.3) and (4.22) (Betti-symmetric:
  /// F_zx = conj(F_xz)). Zero at q = 0. `odd_x`/`odd_y` = false drop the odd
  /// (imaginary) coupling along that axis, as done at Nyquist frequencies.
  static GreenTensor green_tensor(double qx, double qy, double shear_modulus, double poisson, bool odd_x = true,
                                  bool odd_y = true);

  /// u = F * p, all components (6 FFTs). Reuses internal spectral buffers:
  /// one HalfSpace must not be used by two threads at once.
  void displacement(const VectorField& traction, VectorField& u);
  /// u_z from p_z alone, F_zz = 2/(E' q) with E' = E/(1−ν²) (2.35c).
  void normal_displacement(const RealField& p, RealField& u);

  /// E_el = ½ ∫ p·u dA   (4.1)
  static double elastic_energy(const VectorField& traction, const VectorField& u);
  static double elastic_energy(const RealField& p, const RealField& u);

 private:
  Grid2D grid_;
  double young_, poisson_;
  std::shared_ptr<const FFTPlan> plan_;
  ComplexField px_, py_, pz_, ux_, uy_, uz_;
};

}  // namespace wearscale::bem
