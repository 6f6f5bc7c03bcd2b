#pragma once
// The names of quantities that scales exchange, e.g. ShearStrength(Si) or
// InterfaceLaw(SiO2/Si).
#include <compare>
#include <string>

namespace wearscale::coupling {

enum class Quantity {
  ShearStrength,  ///< σ_max(p), σ_dyn(p) of a material (molecular scale)
  InterfaceLaw,   ///< p_crit, μ0, A/A0(p_N), wear coefficient of a pin/disc pair (nano scale)
  MacroResult,    ///< headline results of a macroscale model (friction, wear, contact)
};

std::string to_string(Quantity q);

/// A quantity about a subject: a material ("Si") or a pair ("SiO2/Si").
struct Key {
  Quantity what;
  std::string subject;
  auto operator<=>(const Key&) const = default;
  /// "InterfaceLaw(SiO2/Si)"
  std::string to_string() const;
};

}  // namespace wearscale::coupling
