#pragma once
// Adhesive wear of N equally spaced micro-contacts in 2D (thesis ch. 3,
// Fig. 3.6): N flat junctions of size d, gaps λ, sheared by a uniform
// tangential traction q on a plane-strain half-plane of thickness B.
//
// The elastic energy of loads whose spacing is finite next to the (infinite)
// medium is that of one load N q d (3.11), (3.15), carrying the domain factor
// 𝓜 that replaces the divergent ∫dz/z (3.6). Everything the wear map needs is
// then contained in the critical size d* (3.23): separated particles form iff
// d_r ≥ d* (3.25), a combined particle can form iff d_a ≤ d_r²/d* (3.27),
// equivalently κ = d_r/d_a ≥ √(d*/d_a) (3.29).

namespace wearscale::wear {

/// A row of N micro-contacts of size d with edge-to-edge gaps λ (Fig. 3.6).
struct MicroContactRow {
  int count = 1;        ///< N ≥ 1
  double size = 0.0;    ///< d > 0 [m]
  double spacing = 0.0; ///< λ ≥ 0 [m]

  /// d_r = N d: the real contact size   (3.18)
  double real_size() const;
  /// d_a = N d + (N − 1) λ: the apparent contact size   (3.19)
  double apparent_size() const;
};

/// InputError unless N ≥ 1, d > 0 and λ ≥ 0 (all finite).
void check(const MicroContactRow& row);

/// E_el,Nq = (1 − ν²) B N² d² q² 𝓜 / (π E) [J]   (3.15); N = 1 is (3.13)–(3.14).
double row_elastic_energy_2d(const MicroContactRow& row, double traction, double young, double poisson,
                             double thickness, double domain_factor);

/// E_ad = π γ B s: two semicircular surfaces under a particle of size s [J]   (3.16);
/// s = d_r for N separated particles (3.17), s = d_a for a combined one (3.20).
double adhesive_energy_2d(double particle_size, double surface_energy, double thickness);

/// d* = π² γ E / ((1 − ν²) q² 𝓜) [m]   (3.23). InputError unless γ, E, q, 𝓜 > 0 and −1 < ν ≤ 0.5.
double critical_size_2d(double surface_energy, double young, double poisson, double traction, double domain_factor);

/// R_sep = d_r / d*   (3.24)
double separated_ratio_2d(double real_size, double critical_size);
/// R_comb = d_r² / (d_a d*)   (3.26)
double combined_ratio_2d(double real_size, double apparent_size, double critical_size);

/// κ = d_r / d_a, the fraction of the apparent junction in real contact   (3.28)
double contact_fraction(double real_size, double apparent_size);
/// √(d*/d_a): the least κ from which a junction of apparent size d_a can detach as one particle   (3.29)
double minimum_contact_fraction(double apparent_size, double critical_size);

/// d_a on the separated/combined boundary of the map: d_r²/d*   (3.27)
double combined_boundary_2d(double real_size, double critical_size);

/// The regions of the 2D wear map (Fig. 3.7), each the most severe outcome
/// that is energetically possible.
enum class Region2D : int {
  Inaccessible = -1,  ///< d_a < d_r: not a row of micro-contacts (hatched in Fig. 3.7)
  Plastic = 0,        ///< d_r < d*: the junctions slip or flow plastically
  Separated = 1,      ///< d_r ≥ d* (3.25) but d_a > d_r²/d*: N separate particles
  Combined = 2,       ///< d_a ≤ d_r²/d* (3.27): one combined particle is also possible
};

/// The region of (d_r, d_a) for a critical size d*. InputError unless d_r ≥ 0, d_a > 0, d* > 0.
Region2D classify_2d(double real_size, double apparent_size, double critical_size);

const char* name(Region2D region);

}  // namespace wearscale::wear
