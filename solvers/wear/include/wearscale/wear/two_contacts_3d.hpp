#pragma once
// Adhesive wear of two circular micro-contacts on a 3D half-space (thesis
// §4.4–4.5, Fig. 4.3): diameters d, centres l ≥ d apart on a line at angle θ
// to the uniform tangential traction q = σ_j along x.
//
// Their elastic energy (4.44) is twice that of one contact (4.33) plus an
// interaction term ∝ d⁴ (1 − ν sin²θ)/l, exact for l ≫ d. Unloading them by
// detaching one particle, two separate particles, or one combined particle of
// diameter d_a = d + l (Fig. 4.5) gives the energy ratio (4.48)
//   R = (C_n + (3π/8) C_inter d/l) (d/d*) C_case,
// with C_inter = (1 − ν sin²θ)/(2 − ν) (4.49) between 1/3 (ν = ½, θ = π/2:
// least interaction) and 2/3 (ν = ½, θ = 0: most). The wear map of Fig. 4.6
// is R ≥ 1 for each case over (d/l, d*/l).
#include <array>

namespace wearscale::wear {

/// C_inter = (1 − ν sin²θ)/(2 − ν)   (4.49). InputError unless −1 < ν ≤ 0.5 and θ finite.
double interaction_constant(double poisson, double angle);

/// C_inter at ν = ½, θ = 0: the most elastic interaction (coloured regions of Fig. 4.6).
inline constexpr double max_interaction_constant = 2.0 / 3.0;
/// C_inter at ν = ½, θ = π/2: the least (dashed lines of Fig. 4.6).
inline constexpr double min_interaction_constant = 1.0 / 3.0;

/// E_el,2 = (2 − ν) d³ q²/(6G) + π d⁴ q² (1 − ν sin²θ)/(32 G l) [J]   (4.44).
/// InputError unless 0 < d ≤ l, q, G > 0, −1 < ν ≤ 0.5.
double two_contact_elastic_energy(double diameter, double distance, double angle, double traction,
                                  double shear_modulus, double poisson);

/// The particles the two micro-contacts can detach as (Fig. 4.5), each with its C_n and C_case.
enum class ParticleCase : int {
  OneSeparated = 0,  ///< one particle of diameter d; the other contact stays loaded (C_n = 1, C_case = 1)
  TwoSeparated = 1,  ///< two particles of diameter d (C_n = 2, C_case = ½)
  Combined = 2,      ///< one particle of diameter d_a = d + l (C_n = 2, C_case = d²/d_a²)
};
inline constexpr std::array<ParticleCase, 3> particle_cases = {ParticleCase::OneSeparated,
                                                               ParticleCase::TwoSeparated, ParticleCase::Combined};
const char* name(ParticleCase particle_case);

/// C_n of (4.48): the contacts whose unloading releases energy.
double count_constant(ParticleCase particle_case);
/// C_case of (4.48) at d/l: E_ad of one particle of diameter d over that of the case (4.45)–(4.47).
double case_constant(ParticleCase particle_case, double d_over_l);

/// R of (4.48) at (d/l, d*/l). InputError unless 0 < d/l ≤ 1, d*/l > 0 and 0 < C_inter.
double energy_ratio_3d(ParticleCase particle_case, double d_over_l, double dstar_over_l, double c_inter);

/// d*/l on the line R = 1 of a case at d/l: (C_n + (3π/8) C_inter d/l)(d/l) C_case   (4.48).
/// The case is feasible (R ≥ 1) for every d*/l at or below it.
double boundary_dstar_over_l(ParticleCase particle_case, double d_over_l, double c_inter);

/// R from the energies themselves: ΔE_el ((4.44), minus (4.33) for one
/// particle) over E_ad (4.45)–(4.47), with the material in d* (4.35) never
/// used. For checking (4.48) and for callers holding physical parameters.
double energy_ratio_from_energies(ParticleCase particle_case, double diameter, double distance, double angle,
                                  double traction, double shear_modulus, double poisson, double surface_energy);

/// The regions of the 3D two-contact map (Fig. 4.6), each the most severe
/// detachment with R ≥ 1. For d ≤ l the feasible sets are nested,
/// combined ⊂ two separated ⊂ one separated, since R_comb/R_2sep = 2d²/(d+l)² < 1
/// and R_2sep < R_1sep.
enum class Region3D : int { Plastic = 0, OneSeparated = 1, TwoSeparated = 2, Combined = 3 };
const char* name(Region3D region);

/// The region of (d/l, d*/l) at the interaction C_inter, decided on the exact
/// boundary lines (R ≥ 1 ⇔ d*/l ≤ boundary). Same InputError as energy_ratio_3d.
Region3D classify_3d(double d_over_l, double dstar_over_l, double c_inter);

}  // namespace wearscale::wear
