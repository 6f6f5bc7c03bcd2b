#pragma once
// Stresses in the periodic elastic half-space under surface tractions
// (Appendix A.3, ch. 4): the full tensor at any depth z ≥ 0, from the
// Fourier-space solution of each mode (Boussinesq–Cerruti, Johnson 1985 §2–3).
//
// For a mode q = |q| (c, s) with traction p̂ = (p̂_x, p̂_y, p̂_z), write
// P = p̂_z, T = c p̂_x + s p̂_y (along q), S = −s p̂_x + c p̂_y (across q) and
// ζ = |q| z. In the frame (∥, ⊥, z) the stresses are plane strain for (P, T)
// and antiplane shear for S:
//   σ_∥∥ = (−P + 2iT + (P − iT) ζ) e^{−ζ}     σ_zz = −(P + (P − iT) ζ) e^{−ζ}
//   σ_∥z = (−T + (T + iP) ζ) e^{−ζ}            σ_⊥⊥ = 2ν (−P + iT) e^{−ζ}
//   σ_⊥z = −S e^{−ζ}                           σ_∥⊥ = i S e^{−ζ}
// (an Airy function (A + Bζ)e^{−ζ} and u_⊥ ∝ e^{−ζ}); at z = 0 they meet
// σ_iz = −p_i, and the surface displacements they imply are HalfSpace's
// tensor, coupling (4.22) included. Same conventions: z into the solid,
// p_z > 0 compressive, tension positive. The zero mode is the uniform
// traction with no mean lateral strain: σ_xx = σ_yy = −ν/(1−ν) ⟨p_z⟩. As in
// HalfSpace, the terms odd in q are dropped at Nyquist frequencies.
#include <memory>

#include "wearscale/bem/half_space.hpp"

namespace wearscale::bem {

/// The six components of the (symmetric) stress tensor on a grid [Pa].
struct StressField {
  RealField xx, yy, zz, xy, xz, yz;
  explicit StressField(const Grid2D& g) : xx(g), yy(g), zz(g), xy(g), xz(g), yz(g) {}
  const Grid2D& grid() const { return zz.grid(); }
};

/// The six components of the stress spectrum at one mode.
struct ModeStress {
  std::complex<double> xx, yy, zz, xy, xz, yz;
};

class SubsurfaceStress {
 public:
  /// σ̂ at depth z of r2c mode (i, j) of `g` under the traction spectra px, py,
  /// pz there (the zero mode and the Nyquist averaging included). Every body
  /// that holds these modes (whole or in slabs) takes them from here.
  static ModeStress mode(const Grid2D& g, std::size_t i, std::size_t j, std::complex<double> px,
                         std::complex<double> py, std::complex<double> pz, double depth, double nu);

  /// InputError unless −1 < ν ≤ 0.5 (stresses from tractions do not depend on E).
  SubsurfaceStress(const Grid2D& grid, double poisson);
  /// The stresses in `body` (periodic; it must outlive this object). InputError for a
  /// free boundary: its stresses are not implemented (the periodic solution would show
  /// the images of the load).
  explicit SubsurfaceStress(const HalfSpace& body);

  /// Takes the surface tractions (their spectra are kept for every depth).
  void set_traction(const VectorField& traction);
  /// σ at depth z ≥ 0 below every grid point (z = 0: the surface). InputError if z < 0.
  void stress(double depth, StressField& out);

  const Grid2D& grid() const { return body_->grid(); }
  double poisson() const { return body_->poisson(); }

 private:
  void setup();
  std::unique_ptr<const HalfSpace> owned_;  // the body of the (grid, ν) constructor
  const HalfSpace* body_;
  HalfSpace::Workspace work_;
  std::shared_ptr<const FFTPlan> plan_;
  ComplexField px_, py_, pz_;                   // traction spectra
  ComplexField sxx_, syy_, szz_, sxy_, sxz_, syz_;  // stress spectra (overwritten by the c2r)
};

}  // namespace wearscale::bem
