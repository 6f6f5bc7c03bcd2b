#pragma once
// The thesis' pin-on-disc of §9.3.2 for the tribometer tests: a SiO2 pin on a
// Si disc under h_layer of SiO2, the shear strengths of Fig. 9.18 through the
// junction model; n = 128, L = 2 mm, R = 3 mm, 1 N, 8 mm/s, dt = 0.02 s, 0.5 m
// unless a test sets otherwise.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "wearscale/io/shipped_data.hpp"
#include "wearscale/tribometer/adaptive_wear.hpp"
#include "wearscale/tribometer/friction_average.hpp"
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

// The first contact with the substrate, stepped explicitly with 1/divisor of
// the setup's time step: where the explicit stepping converges to (the thesis
// step's own crossing moves by a step from run to run: its contact chatters,
// and FFTW's measured plans round differently; and it is the first step
// boundary past the crossing, up to one step late).
inline double converged_crossing(PinOnDiscSetup setup, double divisor = 4.0) {
  setup.time_step /= divisor;
  PinOnDisc model(setup);
  while (model.steps() < model.total_steps()) {
    const auto x = model.step();
    if (x.substrate_contact > 0.0) return x.distance;
  }
  return std::numeric_limits<double>::infinity();
}

// The headline figures of a run (as the pin-on-disc backend reports them).
struct Outcome {
  double mu_mean = 0.0, mu_first = 0.0, mu_final = 0.0, pin = 0.0, disc = 0.0;
  double reached = std::numeric_limits<double>::quiet_NaN();  // first distance with contact on the substrate
  double several_grooves = 0.0;  // sliding distance over which two or more grooves were open
  int grooves = 0, grooves_max = 0, solves = 0;
  long iterations = 0;
};

inline Outcome run_outcome(const PinOnDiscSetup& setup, bool adaptive) {
  PinOnDisc model(setup);
  std::vector<double> s, integral;
  Outcome out;
  auto observe = [&](const PinOnDiscSample& x) {
    if (!s.empty() && out.grooves >= 2) out.several_grooves += x.distance - s.back();
    s.push_back(x.distance);
    integral.push_back(x.friction_integral);
    if (x.substrate_contact > 0.0 && std::isnan(out.reached)) out.reached = x.distance;
    out.grooves = x.grooves;
    out.grooves_max = std::max(out.grooves_max, x.grooves);
    out.pin = x.pin_wear;
    out.disc = x.disc_wear;
  };
  if (adaptive)
    run_adaptive(model, {}, observe);
  else
    model.run(observe);
  const FrictionAverage average(s, integral);
  const double period = setup.nonplanar_slope > 0.0 ? setup.tilt_period() : 0.0;
  const auto last = final_window(s.front(), s.back(), period), first = initial_window(s.front(), s.back(), period);
  out.mu_mean = average.mean(s.front(), s.back());
  out.mu_final = average.mean(last.from, last.to);
  out.mu_first = average.mean(first.from, first.to);
  out.solves = model.contact_solves();
  out.iterations = model.contact_iterations();
  return out;
}

// The adaptive run's μ_mean, μ_final and both worn volumes within `rtol` of the reference run's.
inline void expect_same_friction_and_wear(const Outcome& a, const Outcome& reference, double rtol) {
  EXPECT_NEAR(a.mu_mean, reference.mu_mean, rtol * reference.mu_mean);
  EXPECT_NEAR(a.mu_final, reference.mu_final, rtol * reference.mu_final);
  EXPECT_NEAR(a.pin, reference.pin, rtol * reference.pin);
  EXPECT_NEAR(a.disc, reference.disc, rtol * reference.disc);
}

}  // namespace wearscale::tribometer::test_support
