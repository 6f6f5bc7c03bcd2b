#pragma once
// Adaptive integration of the pin-on-disc wear: the surface heights, worn
// volumes and ∫μ ds, y(s), obey dy/ds = f(y) (9.23), integrated over the
// sliding distance with SUNDIALS ARKODE under local error control.
//
// The wear is stiff: a height error on the scale of the contact relaxes over
// about 0.1 mm of sliding (p_crit/E* of the contact's size), so any explicit
// method is held near the thesis' step by stability, not accuracy. The
// integrator is therefore implicit: TR-BDF2 (ARKStep, an L-stable, stiffly
// accurate ESDIRK pair of orders 2 and 3) whose stage equations
// z = a + γ f(z) are solved exactly, one BEM solve each, by
// PinOnDisc::solve_stage (the stage's wear acts as a compliance added to the
// half-space's). The first stage of a step is the last one of the previous
// step, so a step costs two solves. The material switch of each x column
// (the oxide worn through, (9.26)) is located by ARKODE's root finding and
// the integration restarts there, so the rates are smooth within every step.
// On a resolved track the steps are at most one cell long, the strip cells
// under the window wear in the stage with the window's cells over them, and
// the materials are frozen over each step.
//
// Measured on cases/oxide_thickness_sweep.toml (n = 128, 0.5 m): see
// docs/pin_on_disc.md and the README's main-job section.
#include <functional>

#include "wearscale/tribometer/pin_on_disc.hpp"

namespace wearscale::tribometer {

struct AdaptiveOptions {
  double relative_tolerance = 1e-2;  ///< on worn depths, volumes and ∫μ ds (relative to what has worn)
  double absolute_tolerance = 1e-8;  ///< on heights [m] (volumes: × the cell area; ∫μ ds: in m)
  double max_step = 0.01;            ///< largest step in sliding distance [m]
  /// With a rotating tilt, the step is also at most period / steps_per_period
  /// (at 20, μ_final over the last period was 0.7 % off the converged explicit
  /// stepping under the physical reading; at 40, 0.04 %: docs/pin_on_disc.md).
  int steps_per_period = 40;
  /// First step to attempt [m]; 0: velocity × time_step of the setup. A
  /// resumed run passes the step the interrupted one was about to take.
  double initial_step = 0.0;
  /// Whether to observe the starting state (false when resuming: it was observed).
  bool observe_start = true;
  /// The integrator restarts (from the state and the step it proposes) every
  /// this many accepted steps, counted from the start of the run. A
  /// checkpoint taken at a restart resumes bit for bit.
  long restart_every = 20;
  /// Accepted steps before this call (resuming: the count at the checkpoint).
  long steps_done = 0;
};

/// Where the integration stands after an accepted step (for checkpoints).
struct AdaptiveStatus {
  long steps = 0;            ///< accepted steps since the start of the run
  double next_step = 0.0;    ///< the step ARKODE will attempt next [m]
  bool segment_end = false;  ///< a restart point: the place to save a checkpoint
};

/// The largest step the integrator takes for this setup and these options:
/// max_step, at most period / steps_per_period with a tilt, and at most one
/// cell on a resolved track.
double adaptive_step_cap(const PinOnDiscSetup& setup, const AdaptiveOptions& options);

/// Integrates from the model's current distance and state to
/// setup().distance, calling `observe` with the state after every accepted
/// step and at every place a column wears through the oxide, then
/// `after_step` (accepted steps only) if given.
/// InputError for bad options; NumericalError if ARKODE fails (with its flag, the distance and the
/// solver's own error).
void run_adaptive(PinOnDisc& model, const AdaptiveOptions& options,
                  const std::function<void(const PinOnDiscSample&)>& observe,
                  const std::function<void(const AdaptiveStatus&)>& after_step = {});

}  // namespace wearscale::tribometer
