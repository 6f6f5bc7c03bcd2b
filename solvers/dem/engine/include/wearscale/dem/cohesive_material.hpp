#pragma once
// The target material properties of the cohesive DEM pair force (Table 6.3)
// and the particle sizes and time step they imply (6.6), (6.35), (6.62).
#include <optional>
#include <string>

#include "wearscale/materials/material.hpp"

namespace wearscale::dem {

struct CohesiveMaterial {
  std::string name;
  double young = 0.0;             ///< E
  double poisson = 0.0;           ///< ν, at most 1/4 with pair forces (6.52)
  double tensile_strength = 0.0;  ///< σ_m,N
  double shear_strength = 0.0;    ///< σ_m,T
  double surface_energy = 0.0;    ///< γ
  double restitution = 0.0;       ///< η
  double density = 0.0;           ///< ρ
  double scaling_exponent = 0.5;  ///< s ≥ 0 of the d_c rescaling (6.57)
};

/// The patch-test targets of Table 6.4 (no units): E = 1, ν = 0.15,
/// σ_m,N = 0.2, σ_m,T = 0.1, γ = 1.5, η = 0.95, ρ = 1, s = ½.
CohesiveMaterial patch_test_targets();

/// The DEM targets of a material record. η comes from the record (Table 6.5)
/// or `restitution`; InputError when neither gives it.
CohesiveMaterial cohesive_material(const materials::Material& m, double scaling_exponent,
                                   std::optional<double> restitution = std::nullopt);

/// Empty when the targets can be modelled; otherwise why not. In particular
/// ν > 1/4 is refused: A_T (6.52) would be negative, because central pair
/// forces cannot produce a Poisson's ratio above 1/4.
std::string why_not_modelled(const CohesiveMaterial& m);
/// Throws InputError with why_not_modelled() when it is not empty.
void require_modelled(const CohesiveMaterial& m);

/// d_c = 4γE/σ_m,N²  (6.35): above it σ_m,N and γ cannot both be matched.
double critical_diameter(const CohesiveMaterial& m);
/// d_min = 4γ/σ_m,N  (6.62): the largest fracture separation δ_f.
double minimum_diameter(const CohesiveMaterial& m);
/// d* = 32γG/σ_m,T²  (6.65): the junction size above which a sheared DEM
/// junction detaches a particle (materials::critical_size, DemCylinder).
double critical_junction_size(const CohesiveMaterial& m);

/// The interface between two materials, for pairs of particles of different
/// materials: springs in series for E (harmonic mean), the weaker strengths,
/// Berthelot's geometric mean for the adhesion energy (Dupré work
/// 2γ_ab ≈ 2√(γ_a γ_b)), arithmetic means for ν, η, ρ and s.
CohesiveMaterial mix(const CohesiveMaterial& a, const CohesiveMaterial& b);

}  // namespace wearscale::dem
