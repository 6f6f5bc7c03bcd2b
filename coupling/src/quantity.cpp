#include "wearscale/coupling/quantity.hpp"

namespace wearscale::coupling {

std::string to_string(Quantity q) {
  switch (q) {
    case Quantity::ShearStrength: return "ShearStrength";
    case Quantity::InterfaceLaw: return "InterfaceLaw";
    case Quantity::MacroResult: return "MacroResult";
  }
  return "?";
}

std::string Key::to_string() const { return coupling::to_string(what) + "(" + subject + ")"; }

}  // namespace wearscale::coupling
