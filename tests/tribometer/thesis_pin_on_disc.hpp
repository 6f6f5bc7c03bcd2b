#pragma once
// The thesis' pin-on-disc of §9.3.2 for the tribometer tests: a SiO2 pin on a
// Si disc under h_layer of SiO2, the shear strengths of Fig. 9.18 through the
// junction model; n = 128, L = 2 mm, R = 3 mm, 1 N, 8 mm/s, dt = 0.02 s, 0.5 m
// unless a test sets otherwise.
#include <limits>

#include "wearscale/io/shipped_data.hpp"
#include "wearscale/tribometer/pin_on_disc.hpp"

namespace wearscale::tribometer::test_support {

inline PinOnDiscSetup thesis_setup(double layer_thickness) {
  static const materials::StrengthLaw si(materials::shipped_table("thesis", "Si"));
  static const materials::StrengthLaw sio2(materials::shipped_table("thesis", "SiO2"));
  PinOnDiscSetup s;
  s.on_layer = materials::interface_law("SiO2", sio2, "SiO2", sio2);
  s.on_substrate = materials::interface_law("SiO2", sio2, "Si", si);
  s.layer_thickness = layer_thickness;
  return s;
}

// The first contact with the substrate, stepped explicitly with a quarter of
// the setup's time step: where the explicit stepping converges to (the thesis
// step's own crossing moves by a step from run to run: its contact chatters,
// and FFTW's measured plans round differently).
inline double converged_crossing(PinOnDiscSetup setup) {
  setup.time_step /= 4.0;
  PinOnDisc model(setup);
  while (model.steps() < model.total_steps()) {
    const auto x = model.step();
    if (x.substrate_contact > 0.0) return x.distance;
  }
  return std::numeric_limits<double>::infinity();
}

}  // namespace wearscale::tribometer::test_support
