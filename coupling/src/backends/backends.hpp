#pragma once
// Registration functions of the built-in backends (called from backends.cpp).
#include "wearscale/coupling/scale.hpp"

namespace wearscale::coupling {

void register_macro_hertz(ScaleRegistry& registry);

}  // namespace wearscale::coupling
