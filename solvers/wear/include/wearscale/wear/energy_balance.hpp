#pragma once
// The energy balance of adhesive wear (§4.1, §4.3): a wear particle of
// diameter d detaches when the elastic energy released by unloading the
// micro-contacts it removes, ΔE_el, pays for its two new hemispherical
// surfaces, E_ad = π γ d² (4.16): R = ΔE_el / E_ad ≥ 1 (4.17)–(4.18).
// For a single circular micro-contact sheared at its strength σ_j this gives
// the critical diameter d* (4.35), the length every wear map is scaled by.

namespace wearscale::wear {

/// E_ad,1 = π γ d²: the surface energy of a spherical particle of diameter d [J]   (4.16)
double adhesive_energy(double diameter, double surface_energy);

/// E_el,1 = (2 − ν) d³ q² / (12 G): a circular micro-contact of diameter d
/// under a uniform tangential traction q on a half-space [J]   (4.33)
double single_contact_elastic_energy(double diameter, double traction, double shear_modulus, double poisson);

/// d* = 12 π γ G / ((2 − ν) σ_j²) [m]   (4.35). InputError unless γ, G, σ_j > 0 and −1 < ν ≤ 0.5.
double critical_diameter(double surface_energy, double shear_modulus, double poisson, double junction_strength);

}  // namespace wearscale::wear
