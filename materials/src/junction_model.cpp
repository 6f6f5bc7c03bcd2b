#include "wearscale/materials/junction_model.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/roots.hpp"

namespace wearscale::materials {

namespace {
constexpr const char* kModel = "materials/junction-model";

void check_pressure(double p_n, double p_crit) {
  if (!(p_n >= 0.0) || !std::isfinite(p_n))
    throw InputError(fmt::format("junction model: normal pressure {} Pa is not allowed; allowed: ≥ 0", p_n));
  if (!(p_crit > 0.0)) throw InputError(fmt::format("junction model: p_crit = {} Pa; allowed: > 0", p_crit));
}
}  // namespace

double critical_pressure(const StrengthLaw& law) {
  const auto& p = law.table().pressure;
  const auto& s = law.table().sigma_max;
  if (s.front() <= p.front()) return p.front();  // crushed from the start of the table
  for (std::size_t r = 1; r < p.size(); ++r) {
    const double f_hi = s[r] - p[r];
    if (f_hi > 0.0) continue;
    if (p[r] == p[r - 1]) return p[r];  // σ_max drops below p across a jump
    // σ_max − p changes sign on [p[r−1], p[r]]: bracketed root (7.5).
    const double root = find_root([&](double x) { return law.sigma_max(x) - x; }, p[r - 1], p[r], 0.0, kModel);
    return root;
  }
  // The table, not a computation, falls short: bad input naming it.
  throw InputError(fmt::format("{}: σ_max(p) > p up to the end of the table ({:g} GPa), so the critical pressure "
                               "p_crit (σ_max = p) lies beyond it; allowed: a table that reaches σ_max ≤ p (extend it "
                               "to higher pressures)",
                               law.table().origin.empty() ? "strength table" : law.table().origin,
                               law.max_pressure() / 1e9));
}

double minimum_contact_ratio(double p_n, double p_crit) {
  check_pressure(p_n, p_crit);
  return p_n / p_crit;  // (7.6)
}

double tangential_resistance(const StrengthLaw& law, double p_n, double ratio, bool peak) {
  if (!(ratio > 0.0 && ratio <= 1.0))
    throw InputError(fmt::format("junction model: contact ratio A/A0 = {}; allowed: (0, 1]", ratio));
  const double p_loc = p_n / ratio;  // (7.4)
  return ratio * (peak ? law.sigma_max(p_loc) : law.sigma_dyn(p_loc));  // (7.9)
}

double minimum_tangential_resistance(const StrengthLaw& law, double p_n, double p_crit, bool peak) {
  check_pressure(p_n, p_crit);
  return p_n / p_crit * (peak ? law.sigma_max(p_crit) : law.sigma_dyn(p_crit));  // (7.10)
}

double friction_coefficient(const StrengthLaw& law, double p_crit) {
  check_pressure(0.0, p_crit);
  return law.sigma_dyn(p_crit) / p_crit;  // (9.13)
}

double wear_rate(double p_n, double p_crit) {
  check_pressure(p_n, p_crit);
  return p_n / p_crit;  // (9.21)
}

double steady_slope_rms(double p_crit, double e_star) {
  if (!(e_star > 0.0)) throw InputError(fmt::format("junction model: E* = {} Pa; allowed: > 0", e_star));
  return std::sqrt(2.0 * std::numbers::pi) * p_crit / e_star;  // (9.17)
}

InterfaceLaw interface_law(const std::string& a, const StrengthLaw& law_a, const std::string& b,
                           const StrengthLaw& law_b) {
  const double pa = critical_pressure(law_a), pb = critical_pressure(law_b);
  const double mu_a = friction_coefficient(law_a, pa), mu_b = friction_coefficient(law_b, pb);
  InterfaceLaw law;
  law.pair = a + "/" + b;
  const bool a_governs = mu_a <= mu_b;
  law.governing = a_governs ? a : b;
  law.p_crit = a_governs ? pa : pb;
  law.mu0 = a_governs ? mu_a : mu_b;
  return law;
}

}  // namespace wearscale::materials
