#pragma once
// Hertz contact of a sphere on a flat elastic half-space: the closed-form
// reference for the BEM normal contact solver and for the unworn pin.
namespace wearscale::bem {

/// E* of two elastic bodies: 1/E* = (1−ν1²)/E1 + (1−ν2²)/E2   (1.12); InputError
/// unless E > 0 and −1 < ν ≤ 0.5 for both.
double effective_modulus(double e1, double nu1, double e2, double nu2);

struct HertzContact {
  double radius;     ///< sphere radius R [m]
  double load;       ///< normal force F [N]
  double e_star;     ///< effective modulus E* [Pa]

  /// InputError unless R, F and E* are finite and > 0 (every figure below checks it).
  void check() const;
  /// Contact radius a = (3FR / 4E*)^(1/3).
  double contact_radius() const;
  /// Peak pressure p0 = 3F / (2πa²).
  double peak_pressure() const;
  double mean_pressure() const;  ///< F / (πa²) = 2p0/3
  /// Approach of distant points δ = a²/R.
  double approach() const;
  /// p(r) = p0 √(1 − r²/a²) inside the contact, 0 outside.
  double pressure(double r) const;
};

}  // namespace wearscale::bem
