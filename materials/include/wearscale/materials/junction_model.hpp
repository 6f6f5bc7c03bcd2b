#pragma once
// The scale-linking junction model (§7.1.2, §9.3.2): from the molecular
// strengths of a material to the macroscopic tangential resistance, friction
// coefficient, contact ratio and wear rate of a sliding interface.
#include <string>

#include "wearscale/materials/strength_law.hpp"

namespace wearscale::materials {

/// p_crit solving σ_m,c(p) = p (7.5), with σ_m,c = σ_max (9.10): the largest
/// local pressure a junction carries before it is crushed. GSL Brent on the
/// first stretch of the table where σ_max(p) − p changes sign; if the sign
/// changes across a jump of σ_max, p_crit is the jump pressure.
/// NumericalError if σ_max(p) > p over the whole table.
double critical_pressure(const StrengthLaw& law);

/// A_min/A0 = p_N/p_crit   (7.6), (9.11)
double minimum_contact_ratio(double p_n, double p_crit);
/// p_T = (A/A0) σ(p_N A0/A)   (7.9), with σ = σ_dyn for sliding (default) or σ_max
double tangential_resistance(const StrengthLaw& law, double p_n, double contact_ratio, bool peak = false);
/// p_T,min = (p_N/p_crit) σ(p_crit)   (7.10), (9.12)
double minimum_tangential_resistance(const StrengthLaw& law, double p_n, double p_crit, bool peak = false);
/// μ0 = σ_dyn(p_crit)/p_crit   (9.13)
double friction_coefficient(const StrengthLaw& law, double p_crit);
/// Wear volume per apparent area and sliding distance, dV/(A0 ds) = p_N/p_crit   (9.21)
double wear_rate(double p_n, double p_crit);
/// Steady RMS slope h'_RMS = √(2π) p_crit / E*   (9.17)
double steady_slope_rms(double p_crit, double e_star);

/// What the macroscale needs of one sliding interface (§9.3.2).
struct InterfaceLaw {
  std::string pair;        ///< "SiO2/Si": first body / second body
  std::string governing;   ///< the material whose junctions give way
  double p_crit = 0.0;     ///< critical pressure (7.5) [Pa]
  double mu0 = 0.0;        ///< steady friction coefficient (9.13)
  /// A/A0 at apparent pressure p_N (7.6), at most 1 (full contact).
  double contact_ratio(double p_n) const { return p_n < p_crit ? p_n / p_crit : 1.0; }
  /// Wear volume per apparent area and sliding distance (9.21) [1].
  double wear_rate(double p_n) const { return p_n / p_crit; }
};

/// The law of an interface between materials a and b: the one that gives way
/// first in sliding (the lower μ0 = σ_dyn(p_crit)/p_crit) governs — for
/// SiO2–Si the Si beneath the interface (§9.3.2, after (9.15)).
InterfaceLaw interface_law(const std::string& a, const StrengthLaw& law_a, const std::string& b,
                           const StrengthLaw& law_b);

}  // namespace wearscale::materials
