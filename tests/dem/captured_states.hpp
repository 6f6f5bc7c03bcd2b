#pragma once
// The states a DEM run offers at its samples, all kept (the run going on as
// the uninterrupted reference); resume(f) continues from the one a fraction f
// of the way. Shared by the resume tests on one rank and over MPI.
#include <cstddef>
#include <functional>
#include <vector>

#include "wearscale/dem/run_checkpoints.hpp"

namespace wearscale::dem::test_support {

/// Keeps every state offered; resume(f) continues from the state a fraction f of the way.
struct Capture {
  std::vector<CheckpointState> states;
  RunCheckpoints hooks() {
    RunCheckpoints h;
    h.at_sample = [this](long, const std::function<CheckpointState()>& make) { states.push_back(make()); };
    return h;
  }
  RunCheckpoints resume(double fraction) const {
    RunCheckpoints h;
    h.from = &states.at(static_cast<std::size_t>(fraction * static_cast<double>(states.size() - 1)));
    return h;
  }
};

}  // namespace wearscale::dem::test_support
