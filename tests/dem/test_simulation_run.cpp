// Simulation::run and SIGINT/SIGTERM: where a run stops. A driver that runs
// in chunks and checkpoints between them must see its chunk end, so that the
// checkpoint saved after it holds the state the stop found.
#include <algorithm>
#include <cmath>
#include <csignal>
#include <functional>
#include <gtest/gtest.h>
#include <vector>

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

namespace {
// 4608 particles (enough for the threaded loops), a fixed bottom layer and
// a top layer pressed down while dragged along x.
Simulation pressed_block() {
  auto sim = test_support::shaken_hcp_block(12, 12, 8, patch_test_targets(), 0.1, 5);
  const auto& p = sim.particles();
  double lo = p.position[0].z, hi = lo;
  for (const auto& x : p.position) lo = std::min(lo, x.z), hi = std::max(hi, x.z);
  std::vector<std::size_t> bottom, top;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.position[i].z < lo + 10.0) bottom.push_back(i);
    if (p.position[i].z > hi - 10.0) top.push_back(i);
  }
  const double area = sim.box().length().x * sim.box().length().y;
  sim.add_wall(bottom, WallMotion::fixed());
  sim.add_wall(top, WallMotion::pressed(2, 1e-3, area, 1, {1e-3, 0, 0}));
  return sim;
}

void expect_same_state(const Simulation& a, const Simulation& b) {
  ASSERT_EQ(a.step_count(), b.step_count());
  EXPECT_EQ(a.time(), b.time());
  const auto &p = a.particles(), &q = b.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(p.position[i][c], q.position[i][c]) << "particle " << i;
      ASSERT_EQ(p.velocity[i][c], q.velocity[i][c]) << "particle " << i;
      ASSERT_EQ(p.omega[i][c], q.omega[i][c]) << "particle " << i;
    }
  }
  EXPECT_EQ(a.wall(1).displacement.z, b.wall(1).displacement.z);
  EXPECT_EQ(a.wall(1).velocity.z, b.wall(1).velocity.z);
}
}  // namespace

// run() joins the second half-kick of a step and the first of the next into
// one pass when nothing observes between them: the same bits as the steps
// one by one, and as a run whose every step is observed.
TEST(SimulationRun, ARunIsTheSameBitsAsItsStepsOneByOneAndAsAnObservedRun) {
  auto by_steps = pressed_block(), unobserved = pressed_block(), observed = pressed_block();
  for (int s = 0; s < 300; ++s) by_steps.step();
  unobserved.run(300);
  long seen = 0;
  observed.run(300, [&](long) { ++seen; });
  EXPECT_EQ(seen, 300);
  expect_same_state(by_steps, unobserved);
  expect_same_state(by_steps, observed);
  // Moved: the test compares a dynamics, not a block at rest.
  EXPECT_GT(std::abs(by_steps.wall(1).displacement.z), 0.0);
  EXPECT_GT(by_steps.kinetic_energy(), 0.0);
}

// The neighbour list follows a particle's wraps between two builds up to
// 127 periods of the box; one that went farther (it has missed every contact
// on the way) is a numerical failure at the rebuild, not a silent mismatch.
TEST(SimulationRun, AParticleThatCrossedTheBox128TimesBetweenTwoBuildsIsRefusedAtTheRebuild) {
  for (const int periods : {127, 128}) {
    auto sim = small_block();
    sim.step();
    ASSERT_TRUE(sim.box().periodic[0]);
    auto& p = sim.particles();
    const double lo = sim.box().lo.x, length = sim.box().length()[0];
    const int inside = static_cast<int>(std::floor((p.position[0].x - lo) / length));  // the same place, wrapped
    p.position[0].x -= inside * length;
    p.image[0][0] += inside;
    const int image = p.image[0][0];
    p.position[0].x += periods * length;
    // The next rebuild: at once when the list checks displacements, else within its interval.
    if (periods < NeighborList::max_wraps) {
      EXPECT_NO_THROW(sim.run(20));
      EXPECT_NEAR(sim.particles().image[0][0], image + periods, 1) << "wrapped once more or less near a face";
      continue;
    }
    try {
      sim.run(20);
      ADD_FAILURE() << "no error";
    } catch (const NumericalError& e) {
      EXPECT_NE(std::string(e.what()).find("128 periods"), std::string::npos) << e.what();
    }
  }
}
