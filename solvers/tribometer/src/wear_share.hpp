#pragma once
// Internal to the tribometer library: how an interface's wear is shared.
#include <string>

#include "wearscale/materials/junction_model.hpp"

namespace wearscale::tribometer {

inline constexpr const char* kPinOnDiscModel = "tribometer/pin-on-disc";

/// Share of an interface's wear taken by the pin: ½ on a like-on-like
/// interface (9.24), else all on the body whose junctions give way (9.26).
inline double pin_share(const materials::InterfaceLaw& law) {
  const auto slash = law.pair.find('/');
  const std::string pin = law.pair.substr(0, slash), other = law.pair.substr(slash + 1);
  if (pin == other) return 0.5;
  return law.governing == pin ? 1.0 : 0.0;
}

}  // namespace wearscale::tribometer
