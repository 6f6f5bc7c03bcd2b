#pragma once
// An adaptive pin-on-disc run killed right after the checkpoint of a restart
// and resumed in a fresh model (a new process), beside the same run
// uninterrupted: what the restart tests compare.
#include <stdexcept>
#include <vector>

#include "wearscale/io/checkpoint.hpp"
#include "wearscale/tribometer/adaptive_wear.hpp"
#include "wearscale/tribometer/pin_on_disc.hpp"

namespace wearscale::tribometer::test_support {

struct AdaptiveRestart {
  std::vector<PinOnDiscSample> uninterrupted, resumed;  ///< every sample of each run
  long uninterrupted_steps = 0;                                    ///< steps of the uninterrupted run
  AdaptiveStatus stopped_at;                           ///< where the first process was killed
};

/// The run of `setup` stopped at the first restart after `stop_after` steps
/// and resumed from its saved state. Throws std::logic_error if the run ends
/// before it could be stopped.
inline AdaptiveRestart adaptive_restart(const PinOnDiscSetup& setup,
                                        const AdaptiveOptions& options, long stop_after) {

  AdaptiveRestart out;
  PinOnDisc whole(setup);
  run_adaptive(whole, options, [&](const PinOnDiscSample& x) { out.uninterrupted.push_back(x); },
               [&](const AdaptiveStatus& status) { out.uninterrupted_steps = status.steps; });
  struct Killed {};
  PinOnDisc first(setup);
  CheckpointState saved;
  try {
    run_adaptive(first, options, [&](const PinOnDiscSample& x) { out.resumed.push_back(x); },
                 [&](const AdaptiveStatus& status) {
                   if (!status.segment_end || status.steps < stop_after) return;
                   first.save(saved);
                   out.stopped_at = status;
                   throw Killed{};  // right after its checkpoint
                 });
    throw std::logic_error("the run ended before its restart after the stop step");
  } catch (const Killed&) {
  }
  PinOnDisc second(setup);
  second.restore(saved);
  AdaptiveOptions resume = options;
  resume.initial_step = out.stopped_at.next_step;
  resume.steps_done = out.stopped_at.steps;
  resume.observe_start = false;
  run_adaptive(second, resume, [&](const PinOnDiscSample& x) { out.resumed.push_back(x); });
  return out;
}

}  // namespace wearscale::tribometer::test_support
