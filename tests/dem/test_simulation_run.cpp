// Simulation::run and SIGINT/SIGTERM: where a run stops. A driver that runs
// in chunks and checkpoints between them must see its chunk end, so that the
// checkpoint saved after it holds the state the stop found.
#include <csignal>
#include <functional>
#include <gtest/gtest.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/dem/cohesive_material.hpp"
#include "shaken_hcp_block.hpp"

using namespace wearscale;
using namespace wearscale::dem;

namespace {
Simulation small_block() { return test_support::shaken_hcp_block(3, 2, 2, patch_test_targets(), 0.1, 3); }

// Requests a stop after the second step of the call.
struct StopAfterSecondStep {
  long first = -1;
  void operator()(long step) {
    if (first < 0) first = step;
    if (step == first + 1) request_interrupt(SIGINT);
  }
};
}  // namespace

TEST(SimulationRun, AStopInsideALongCallEndsItAtTheNextThousandTwentyFourthStep) {
  auto sim = small_block();
  StopAfterSecondStep stop;
  EXPECT_THROW(sim.run(3000, std::ref(stop)), Interrupted);
  EXPECT_EQ(sim.step_count(), 1024);  // checked every 1024 steps (and after 5 s of a call)
  clear_interrupt();
}

TEST(SimulationRun, AChunkOfACheckpointingDriverRunsToItsEndAndTheNextCallStops) {
  auto sim = small_block();
  StopAfterSecondStep stop;
  EXPECT_NO_THROW(sim.run(3000, std::ref(stop), Simulation::StopInside::No));
  EXPECT_EQ(sim.step_count(), 3000);
  EXPECT_THROW(sim.run(10, {}, Simulation::StopInside::No), Interrupted);  // at its start: nothing run
  EXPECT_EQ(sim.step_count(), 3000);
  clear_interrupt();
}
