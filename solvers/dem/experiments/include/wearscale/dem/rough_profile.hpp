#pragma once
// A periodic self-affine height profile along one axis, h(x) over [0, L):
// the roughness of the quasi-2D rough surfaces of §7.2. A sum of Fourier
// modes q_k = 2πk/L, k = k_min..k_max, with random phases and amplitudes
// ∝ q^−(H+½) (a 1D power spectrum ∝ q^−(1+2H)), scaled so that its
// arithmetic mean deviation Sa is the requested one.
#include <cstdint>
#include <vector>

namespace wearscale::dem {

struct RoughProfileSpec {
  double length = 0.0;        ///< period L
  double sa = 0.0;            ///< arithmetic mean deviation Sa = ⟨|h − ⟨h⟩|⟩
  double hurst = 0.8;         ///< Hurst exponent H in (0, 1]
  int k_min = 1;              ///< longest wavelength L / k_min
  int k_max = 8;              ///< shortest wavelength L / k_max
  std::uint64_t seed = 1;
};

class RoughProfile {
 public:
  /// InputError unless L > 0, Sa ≥ 0, 0 < H ≤ 1, 1 ≤ k_min ≤ k_max.
  explicit RoughProfile(const RoughProfileSpec& spec);
  /// h(x), periodic in L, of zero mean.
  double operator()(double x) const;
  double length() const { return length_; }

 private:
  double length_ = 0.0;
  std::vector<double> wavenumber_, amplitude_, phase_;
};

}  // namespace wearscale::dem
