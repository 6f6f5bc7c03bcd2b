#pragma once
// The quantities that scales exchange, e.g. ShearStrength(Si) or
// InterfaceLaw(SiO2/Si), each with the one C++ type that carries it.
#include <compare>
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "wearscale/materials/junction_model.hpp"
#include "wearscale/materials/strength_law.hpp"

namespace wearscale::coupling {

enum class Quantity {
  ShearStrength,  ///< σ_max(p), σ_dyn(p) of a material (molecular scale)
  InterfaceLaw,   ///< p_crit, μ0, A/A0(p_N), wear coefficient of a pin/disc pair (nano scale)
  MacroResult,    ///< headline results of a macroscale model (friction, wear, contact)
};
inline constexpr std::size_t quantity_count = 3;

/// The C++ type of each quantity, declared once here: Exchange::put and get
/// are checked against it at compile time.
template <Quantity Q>
struct QuantityTraits;
template <>
struct QuantityTraits<Quantity::ShearStrength> {
  using type = materials::StrengthLaw;
};
template <>
struct QuantityTraits<Quantity::InterfaceLaw> {
  using type = materials::InterfaceLaw;
};
template <>
struct QuantityTraits<Quantity::MacroResult> {
  using type = nlohmann::json;  ///< {name: {value, unit, description}}, as RunContext::results()
};
template <Quantity Q>
using QuantityType = typename QuantityTraits<Q>::type;

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
