// Checkpoints of DEM runs: a run stopped, saved and resumed in a system
// set up afresh continues bit for bit as if it had never stopped.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>

#include "input_error_of.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/dem/anchor_block.hpp"
#include "wearscale/dem/junction_strength.hpp"
#include "wearscale/materials/material.hpp"

using namespace wearscale;
using namespace wearscale::dem;

namespace {

// The anchor block of the LAMMPS benchmark (Hooke law with tangential
// history), stirred with seeded random velocities so that pairs slide, come
// and go across neighbour-list rebuilds.
Simulation stirred_block() {
  Simulation sim = make_anchor_block({4, 10});
  std::mt19937 rng(7);
  std::normal_distribution<double> v(0.0, 0.02);
  auto& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!p.frozen(i)) p.velocity[i] = {v(rng), v(rng), v(rng)};
  return sim;
}

void expect_same_state(const Simulation& a, const Simulation& b) {
  ASSERT_EQ(a.particles().size(), b.particles().size());
  EXPECT_EQ(a.step_count(), b.step_count());
  EXPECT_EQ(a.time(), b.time());
  for (std::size_t i = 0; i < a.particles().size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(a.particles().position[i][c], b.particles().position[i][c]) << "particle " << i;
      ASSERT_EQ(a.particles().velocity[i][c], b.particles().velocity[i][c]) << "particle " << i;
      ASSERT_EQ(a.particles().omega[i][c], b.particles().omega[i][c]) << "particle " << i;
    }
  }
  EXPECT_EQ(a.neighbor_list().history(), b.neighbor_list().history());
}

JunctionStrengthSpec small_junction() {
  JunctionStrengthSpec s;
  s.top = s.bottom = cohesive_material(materials::silica(), 0.5);
  s.cell.d0 = 1.5e-9;
  s.cell.length = 12;
  s.cell.height = 6;
  s.contact_ratio = 0.5;
  s.pressure = 1e9;
  s.velocity = 50.0;
  s.sliding_distance = 0.3;
  s.record_every = 100;
  return s;
}

}  // namespace

TEST(SimulationState, AResumedRunContinuesBitForBit) {
  Simulation straight = stirred_block();
  straight.run(300);

  Simulation first = stirred_block();
  first.run(170);  // between two list rebuilds (every 10 steps): the list is restored, not rebuilt
  CheckpointState saved;
  first.save_state(saved);
  Simulation resumed = make_anchor_block({4, 10});  // set up afresh, still at rest
  resumed.restore_state(saved);
  resumed.run(130);
  expect_same_state(straight, resumed);
}

TEST(SimulationState, ARunSavedBeforeItsFirstStepStartsLikeANewOne) {
  Simulation straight = stirred_block();
  straight.run(25);
  Simulation fresh = stirred_block();
  CheckpointState saved;
  fresh.save_state(saved);
  Simulation resumed = make_anchor_block({4, 10});
  resumed.restore_state(saved);
  resumed.run(25);
  expect_same_state(straight, resumed);
}

// A state saved before lists knew several periodic images (format 1: shift
// indices into the 27 nearest images, no "images" entry) still resumes bit
// for bit.
TEST(SimulationState, AStateOfFormatOneResumesBitForBit) {
  Simulation straight = stirred_block();
  straight.run(300);
  Simulation first = stirred_block();
  first.run(170);
  CheckpointState saved;
  first.save_state(saved);
  PeriodicImages now;
  const auto& reach = saved.array("dem.list.images");
  for (std::size_t a = 0; a < 3; ++a) now.reach[a] = static_cast<int>(reach[a]);
  const PeriodicImages nearest;  // the 27 of format 1
  CheckpointState old;
  for (const auto& [name, values] : saved.arrays()) {
    if (name == "dem.list.images") continue;
    std::vector<double> v = values;
    if (name == "dem.list.shifts")
      for (double& s : v) {
        const auto shift = now.shift(static_cast<std::uint8_t>(s));
        s = nearest.index(shift[0], shift[1], shift[2]);
      }
    old.put(name, v);
  }
  for (const auto& [name, text] : saved.texts()) old.put_text(name, text);
  old.put_text("dem.format", "wearscale-dem-state-1");
  Simulation resumed = make_anchor_block({4, 10});
  resumed.restore_state(old);
  resumed.run(130);
  expect_same_state(straight, resumed);
}

TEST(SimulationState, RefusesAStateThatIsNotADemState) {
  Simulation sim = stirred_block();
  CheckpointState other;
  other.put("tribometer.distance", 1.0);
  EXPECT_THAT(input_error_of([&] { sim.restore_state(other); }), testing::HasSubstr("not a DEM state"));
  CheckpointState truncated;
  sim.save_state(truncated);
  truncated.put("dem.velocity", std::vector<double>(5, 0.0));
  EXPECT_THAT(input_error_of([&] { sim.restore_state(truncated); }), testing::HasSubstr("dem.velocity"));
}

TEST(SimulationState, RefusesTheStateOfTheSameParticlesNumberedOtherwise) {
  // A checkpoint restored into a set-up of as many particles must hold them in
  // the same order: the study's walls and subsets are the set-up's indices.
  Simulation saved = stirred_block();
  saved.particles().radius[0] *= 0.99;  // one particle apart from the others
  CheckpointState state;
  saved.save_state(state);
  Simulation renumbered = stirred_block();
  renumbered.particles().radius[1] *= 0.99;  // that particle numbered 1, not 0
  EXPECT_THAT(input_error_of([&] { renumbered.restore_state(state); }),
              testing::HasSubstr("the checkpoint's particles are not this run's"));
  Simulation same = stirred_block();
  same.particles().radius[0] *= 0.99;
  EXPECT_NO_THROW(same.restore_state(state));
}

// The §7.1.1 junction study, stopped after a few samples and resumed from its
// checkpoint: the same peak and steady p_T, contact ratios and history.
TEST(SimulationState, AJunctionRunResumedFromItsCheckpointGivesTheSameResult) {
  const JunctionStrengthSpec spec = small_junction();
  const JunctionStrengthResult straight = run_junction_strength(spec);

  CheckpointState saved;
  long saved_at = 0;
  struct Stop {};
  RunCheckpoints stop_after_sliding_starts;
  stop_after_sliding_starts.at_sample = [&](long step, const std::function<CheckpointState()>& make) {
    if (static_cast<double>(step) < 0.5 * static_cast<double>(straight.steps)) return;
    saved = make();
    saved_at = step;
    throw Stop{};  // the run is killed here
  };
  EXPECT_THROW(run_junction_strength(spec, {}, stop_after_sliding_starts), Stop);
  ASSERT_GT(saved_at, 0);

  RunCheckpoints resume;
  resume.from = &saved;
  const JunctionStrengthResult resumed = run_junction_strength(spec, {}, resume);
  EXPECT_EQ(resumed.peak_tangential, straight.peak_tangential);
  EXPECT_EQ(resumed.steady_tangential, straight.steady_tangential);
  EXPECT_EQ(resumed.normal, straight.normal);
  EXPECT_EQ(resumed.loaded_contact_ratio, straight.loaded_contact_ratio);
  EXPECT_EQ(resumed.final_contact_ratio, straight.final_contact_ratio);
  EXPECT_EQ(resumed.rigid_residual, straight.rigid_residual);
  ASSERT_EQ(resumed.history.size(), straight.history.size());
  for (std::size_t k = 0; k < straight.history.size(); ++k)
    EXPECT_EQ(resumed.history[k].tangential_force, straight.history[k].tangential_force) << "sample " << k;
}
