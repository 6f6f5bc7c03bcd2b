#pragma once
// The specific wear rate k = V / (F_N s) of Archard's law, the figure
// tribologists compare across tests, in the unit they quote it in: mm³/(N·m).
#include <limits>

namespace wearscale::tribometer {

/// The unit of specific_wear_rate(), as results and tables name it.
inline constexpr const char* specific_wear_rate_unit = "mm^3/(N·m)";

/// k = V / (F_N s) [mm³/(N·m)] of a worn `volume` [m³] after sliding
/// `distance` [m] under `normal_load` [N]; NaN before any sliding (s = 0).
inline double specific_wear_rate(double volume, double normal_load, double distance) {
  if (!(distance > 0.0) || !(normal_load > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return volume * 1e9 / (normal_load * distance);  // Archard: k = V/(F_N s); 1 m³ = 1e9 mm³
}

}  // namespace wearscale::tribometer
