#include "result_bounds.hpp"

#include <cmath>

#include <fmt/format.h>

namespace wearscale::studies {

namespace {

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }
bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

std::string result_outside_bounds(const std::string& name, double value, const std::string& unit) {
  const auto outside = [&](const char* why) {
    return fmt::format("{} = {:g}{}: {}", name, value, unit.empty() || unit == "1" ? "" : " " + unit, why);
  };
  if (!std::isfinite(value)) return outside("not a number (NaN or infinite)");
  // Sizes of what a run measures or wears: volumes, areas, lengths slid, times.
  if ((unit == "m^3" || unit == "m^2" || unit == "s") && value < 0.0) return outside("a volume, area or time is ≥ 0");
  if ((name == "distance" || name == "substrate_reached_at" || name == "contact_radius" || name == "h_rms" ||
       name == "Sa") &&
      value < 0.0)
    return outside("a distance or roughness is ≥ 0");
  // Friction coefficients (μ, μ0 of an interface, the averages of μ) and RMS slopes.
  if ((starts_with(name, "mu_") || starts_with(name, "mu0_") || name == "h_prime_rms" || name == "hprime_rms") &&
      value < 0.0)
    return outside("a friction coefficient or an RMS slope is ≥ 0");
  // Shares of an area or of points.
  if (ends_with(name, "_fraction") && !(value >= 0.0 && value <= 1.0)) return outside("a fraction is within [0, 1]");
  // Critical pressures (7.5) and the strengths of a table.
  if (starts_with(name, "p_crit_") && !(value > 0.0)) return outside("a critical pressure is > 0");
  if ((starts_with(name, "sigma_max_") || starts_with(name, "sigma_dyn_")) && value < 0.0)
    return outside("a shear strength is ≥ 0");
  // Elastic constants a run measures (the DEM patch test).
  if (name == "young" && !(value > 0.0)) return outside("a Young's modulus is > 0");
  if (name == "poisson" && !(value > -1.0 && value < 0.5)) return outside("a Poisson's ratio is within (−1, ½)");
  return {};
}

std::string results_problem(const nlohmann::json& results) {
  if (!results.is_object()) return "its results are not a table of figures";
  for (const auto& [name, r] : results.items()) {
    if (!r.is_object() || !r.contains("value") || !r["value"].is_number() || !r.contains("unit") ||
        !r["unit"].is_string())
      return fmt::format("result '{}' is not a figure with a value and a unit", name);
    const std::string why = result_outside_bounds(name, r["value"].get<double>(), r["unit"].get<std::string>());
    if (!why.empty()) return why;
  }
  return {};
}

}  // namespace wearscale::studies
