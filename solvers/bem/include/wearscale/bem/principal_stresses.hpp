#pragma once
// Principal stresses σ_I ≥ σ_II ≥ σ_III of a stress tensor field and the
// maximum shear stress τ_m = (σ_I − σ_III)/2 (Appendix A.3). σ_I is the
// maximum tensile stress of the crack initiation criterion (4.24).
#include <array>

#include "wearscale/bem/subsurface_stress.hpp"

namespace wearscale::bem {

struct PrincipalStresses {
  RealField first, second, third;  ///< σ_I ≥ σ_II ≥ σ_III [Pa]
  RealField max_shear;             ///< τ_m = (σ_I − σ_III)/2 [Pa]
  explicit PrincipalStresses(const Grid2D& g) : first(g), second(g), third(g), max_shear(g) {}
};

/// Eigenvalues of the symmetric tensor [[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]],
/// largest first (closed form, Smith 1961).
std::array<double, 3> principal_values(double xx, double yy, double zz, double xy, double xz, double yz);

/// σ_I, σ_II, σ_III and τ_m at every point of `stress`.
void principal_stresses(const StressField& stress, PrincipalStresses& out);

}  // namespace wearscale::bem
