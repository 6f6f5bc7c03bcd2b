#pragma once
// Registration functions of the built-in backends (called from backends.cpp).
#include "wearscale/coupling/scale.hpp"

namespace wearscale::coupling {

void register_macro_hertz(ScaleRegistry& registry);
void register_molecular_table(ScaleRegistry& registry);
void register_molecular_ideal(ScaleRegistry& registry);
void register_molecular_lammps(ScaleRegistry& registry);
void register_nano_analytic(ScaleRegistry& registry);
void register_nano_dem(ScaleRegistry& registry);
void register_macro_pin_on_disc(ScaleRegistry& registry);

}  // namespace wearscale::coupling
