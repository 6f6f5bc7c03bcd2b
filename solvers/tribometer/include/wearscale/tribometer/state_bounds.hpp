#pragma once
// The physical bounds of a pin-on-disc state and of its samples, one check for
// every way a state arises: computed by a step (a state outside them is a
// numerical failure) or restored from a checkpoint (a state outside them is
// no state a run reaches: the checkpoint is refused, whatever its checksum
// says). Distances within the run's, worn volumes and friction ≥ 0, shares
// within [0, 1], counts whole and within what the run can take, every number
// finite.
#include <string>

#include "wearscale/core/checkpoint_state.hpp"
#include "wearscale/tribometer/pin_on_disc.hpp"

namespace wearscale::tribometer {

/// "" if `x` is a sample a run of `setup` can produce, else its first problem ("friction = -1: ...").
std::string sample_problem(const PinOnDiscSample& x, const PinOnDiscSetup& setup);

/// Counts (steps, iterations) are checked by wearscale::count_problem (core/checkpoint_state.hpp).
using wearscale::count_problem;

}  // namespace wearscale::tribometer
