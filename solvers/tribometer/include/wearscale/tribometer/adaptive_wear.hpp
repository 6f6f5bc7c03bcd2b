#pragma once
// Adaptive time integration of the pin-on-disc wear: the surface heights and
// worn volumes y(s) obey dy/ds = rate(y) (9.23), integrated over the sliding
// distance with SUNDIALS ARKODE's explicit embedded Runge–Kutta pair
// (Heun–Euler 2(1)) and local error control, instead of the thesis' fixed step.
#include <functional>

#include "wearscale/tribometer/pin_on_disc.hpp"

namespace wearscale::tribometer {

// Defaults: 0.1 µm on heights, a fifth of the thinnest oxide of the thesis'
// sweep; measured on h_layer = 0.5 µm over 0.05 m: 180 contact solves
// against 314 for the explicit step, worn volume within 0.3 %.
struct AdaptiveOptions {
  double relative_tolerance = 1e-2;
  double absolute_tolerance = 1e-7;  ///< on heights [m] (volumes are scaled to match)
  double max_step = 0.01;            ///< largest step in sliding distance [m]
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

/// Integrates from the model's current distance and state to
/// setup().distance, calling `observe` with the state after every accepted
/// step (one extra contact solve each), then `after_step` if given. The
/// step-size controller starts afresh at every restart (restart_every), whose
/// first step is the one the controller had proposed, growth limited as on
/// any step.
/// NumericalError if ARKODE fails (with its flag, the distance and the
/// solver's own error).
void run_adaptive(PinOnDisc& model, const AdaptiveOptions& options,
                  const std::function<void(const PinOnDiscSample&)>& observe,
                  const std::function<void(const AdaptiveStatus&)>& after_step = {});

}  // namespace wearscale::tribometer
