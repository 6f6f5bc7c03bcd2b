#include "wearscale/tribometer/state_bounds.hpp"

#include <cmath>

#include <fmt/format.h>

namespace wearscale::tribometer {

std::string sample_problem(const PinOnDiscSample& x, const PinOnDiscSetup& setup) {
  const auto finite_in = [](const char* name, double v, double low, double high) -> std::string {
    if (std::isfinite(v) && v >= low && v <= high) return {};
    if (std::isinf(high)) return fmt::format("{} = {:g}; allowed: finite and ≥ {:g}", name, v, low);
    return fmt::format("{} = {:g}; allowed: within [{:g}, {:g}]", name, v, low, high);
  };
  constexpr double inf = HUGE_VAL;
  // The last step lands on the distance (to rounding).
  const double distance = setup.distance * (1.0 + 1e-9);
  for (const std::string& problem :
       {finite_in("distance", x.distance, 0.0, distance), finite_in("friction", x.friction, 0.0, inf),
        finite_in("friction integral", x.friction_integral, 0.0, inf), finite_in("pin wear", x.pin_wear, 0.0, inf),
        finite_in("disc wear", x.disc_wear, 0.0, inf), finite_in("contact fraction", x.contact_fraction, 0.0, 1.0),
        finite_in("layer contact share", x.layer_contact, 0.0, 1.0),
        finite_in("substrate contact share", x.substrate_contact, 0.0, 1.0),
        finite_in("peak pressure", x.max_pressure, 0.0, inf),
        count_problem("BEM iterations", x.iterations, 0.0, 1e9),
        count_problem("grooves", x.grooves, 0.0, static_cast<double>(setup.grid))})
    if (!problem.empty()) return problem;
  return {};
}

}  // namespace wearscale::tribometer
