// The one list of built-in backends. A new backend is one file in
// coupling/src/backends/ with a register_* function, plus one line here.
#include "backends/backends.hpp"

namespace wearscale::coupling {

const ScaleRegistry& scale_registry() {
  static const ScaleRegistry registry = [] {
    ScaleRegistry r;
    register_macro_hertz(r);
    register_molecular_table(r);
    register_molecular_ideal(r);
    register_molecular_lammps(r);
    register_nano_analytic(r);
    register_nano_dem(r);
    register_macro_pin_on_disc(r);
    return r;
  }();
  return registry;
}

}  // namespace wearscale::coupling
