// The DEM studies a user runs on their own (`wearscale dem ...`) can be
// resumed: each offers its state after every sample, and a run set up
// afresh from that state ends bit for bit as the run that never stopped -
// the sheared junction (§6.3), sheared rough surfaces (§7.2), trapped
// particles (§7.3), the three patch tests (§6.2) and the oxidized asperity
// (§9.3.3), from a state taken in
// each of them. A state of another study is refused, naming the entry.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>

#include "input_error_of.hpp"
#include "reduced_oxide_asperity.hpp"
#include "study_resume_support.hpp"
#include "wearscale/dem/oxide_asperity.hpp"
#include "wearscale/dem/patch_test.hpp"
#include "wearscale/dem/rough_shear.hpp"
#include "wearscale/dem/sheared_junction.hpp"
#include "wearscale/dem/trapped_particles.hpp"
#include "wearscale/materials/material.hpp"

using namespace wearscale;
using namespace wearscale::dem;

namespace {
constexpr double d0 = 6e-9;  // coarse: a few hundred particles, a second per run
using test_support::Capture;
using test_support::expect_same_history;
SlidingCellSpec coarse_cell() { return test_support::coarse_cell(d0); }

// A junction of D = 20 nm slid by one d0.
ShearedJunctionSpec coarse_junction() {
  ShearedJunctionSpec s;
  s.material = cohesive_material(materials::silica(), 0.5);
  s.diameter = 20e-9;
  s.d0 = d0;
  s.velocity = 50.0;
  s.sliding_distance = d0;
  return s;
}

}  // namespace

TEST(StudyResume, AShearedJunctionResumedMidSlideEndsBitForBitAsTheUninterruptedRun) {
  const ShearedJunctionSpec s = coarse_junction();
  Capture capture;
  const auto straight = run_sheared_junction(s, {}, capture.hooks());
  ASSERT_GE(capture.states.size(), 3u);
  const auto resumed = run_sheared_junction(s, {}, capture.resume(0.5));
  EXPECT_EQ(resumed.peak_tangential_force, straight.peak_tangential_force);
  EXPECT_EQ(resumed.rigid_residual, straight.rigid_residual);
  EXPECT_EQ(resumed.rolling_rate, straight.rolling_rate);
  EXPECT_EQ(resumed.detached_cluster, straight.detached_cluster);
  EXPECT_EQ(resumed.detached_diameter, straight.detached_diameter);
  ASSERT_EQ(resumed.history.size(), straight.history.size());
  for (std::size_t k = 0; k < straight.history.size(); ++k) {
    EXPECT_EQ(resumed.history[k].tangential_force, straight.history[k].tangential_force) << "sample " << k;
    EXPECT_EQ(resumed.history[k].normal_force, straight.history[k].normal_force) << "sample " << k;
  }
}

TEST(StudyResume, ShearedRoughSurfacesResumedInTheWindowEndBitForBitAsTheUninterruptedRun) {
  RoughShearSpec s;
  s.cell = coarse_cell();
  s.cell.box = {10 * d0, 3.5 * d0, 10 * d0};
  s.roughness = 0.04;
  Capture capture;
  const auto straight = run_rough_shear(s, {}, capture.hooks());
  ASSERT_GE(capture.states.size(), 3u);
  // The last sample before the end lies in the rigid-fit window (the last
  // fifth of the slide): its state carries the window's first positions.
  const auto resumed = run_rough_shear(s, {}, capture.resume(1.0));
  expect_same_history(resumed.history, straight.history);
  EXPECT_EQ(resumed.peak_tangential_force, straight.peak_tangential_force);
  EXPECT_EQ(resumed.friction, straight.friction);
  EXPECT_EQ(resumed.worn, straight.worn);
  EXPECT_EQ(resumed.wear_particle, straight.wear_particle);
  EXPECT_EQ(resumed.wear_particle_residual, straight.wear_particle_residual);
  EXPECT_EQ(resumed.regime, straight.regime);

  // The state of another study is not this one's.
  TrappedParticlesSpec t;
  t.cell = s.cell;
  t.count = 1;
  t.diameter = 3.5 * d0;
  t.cell.box = {10 * d0, 3.5 * d0, 12 * d0};
  EXPECT_THAT(input_error_of([&] { run_trapped_particles(t, {}, capture.resume(1.0)); }),
              testing::AnyOf(testing::HasSubstr("trapped_particles.tallies"), testing::HasSubstr("dem.")));
}

TEST(StudyResume, TrappedParticlesResumedMidSlideEndBitForBitAsTheUninterruptedRun) {
  test_support::expect_trapped_particles_resume_bit_for_bit(coarse_cell());
}

// The patch tests run one after the other (elastic, tension, shear); a state
// taken in any of them resumes that test and runs those after it.
TEST(StudyResume, APatchTestResumedInEachOfItsThreeTestsEndsBitForBitAsTheUninterruptedRun) {
  PatchTestSpec s;
  s.material = patch_test_targets();
  s.material.poisson = 0.1;
  s.d0 = 90.0;  // 0.6 d_c
  s.length = 8.0;
  s.strain_rate = 1e-4;
  std::map<int, CheckpointState> third_of_each;  // the state at the third sample of each test
  std::map<int, int> seen;
  RunCheckpoints keep;
  keep.at_sample = [&](long, const std::function<CheckpointState()>& make) {
    CheckpointState st = make();
    const int phase = static_cast<int>(st.scalar("patch_test.phase"));
    if (++seen[phase] == 3) third_of_each[phase] = std::move(st);
  };
  const auto straight = run_patch_test(s, {}, keep);
  ASSERT_EQ(third_of_each.size(), 3u) << "a state from the elastic, tensile and shear tests";
  ASSERT_TRUE(straight.tensile_strength && straight.shear_strength);
  for (const auto& [phase, state] : third_of_each) {
    SCOPED_TRACE("resumed in test " + std::to_string(phase));
    RunCheckpoints from;
    from.from = &state;
    const auto resumed = run_patch_test(s, {}, from);
    EXPECT_EQ(resumed.particles, straight.particles);
    EXPECT_EQ(resumed.young, straight.young);
    EXPECT_EQ(resumed.poisson, straight.poisson);
    EXPECT_EQ(resumed.elastic_steps, straight.elastic_steps);
    EXPECT_EQ(resumed.tensile_strength, straight.tensile_strength);
    EXPECT_EQ(resumed.shear_strength, straight.shear_strength);
    EXPECT_EQ(resumed.strength_steps, straight.strength_steps);
  }
}

// The oxidized asperity (§9.3.3): a state taken while loading and one taken
// while sliding (after the body's first window) both resume to the
// uninterrupted run's history, body and trench, bit for bit.
TEST(StudyResume, TheOxidizedAsperityResumedLoadingOrSlidingEndsBitForBitAsTheUninterruptedRun) {
  const auto s = test_support::reduced_oxide_asperity(3 * d0);  // a body window after 2 d0, one at the end
  Capture capture;
  const auto straight = run_oxide_asperity(s, {}, capture.hooks());
  ASSERT_GE(capture.states.size(), 8u);
  for (const double at : {0.05, 0.8}) {
    SCOPED_TRACE("resumed " + std::to_string(at) + " of the way");
    const auto resumed = run_oxide_asperity(s, {}, capture.resume(at));
    ASSERT_EQ(resumed.history.size(), straight.history.size());
    for (std::size_t k = 0; k < straight.history.size(); ++k) {
      EXPECT_EQ(resumed.history[k].tangential_force, straight.history[k].tangential_force) << "sample " << k;
      EXPECT_EQ(resumed.history[k].body_particles, straight.history[k].body_particles) << "sample " << k;
      EXPECT_EQ(resumed.history[k].trench_depth, straight.history[k].trench_depth) << "sample " << k;
    }
    EXPECT_EQ(resumed.rotation, straight.rotation);
    EXPECT_EQ(resumed.travel, straight.travel);
    EXPECT_EQ(resumed.final_body, straight.final_body);
    EXPECT_EQ(resumed.friction, straight.friction);
    EXPECT_EQ(resumed.reached_substrate_at, straight.reached_substrate_at);
  }
}

TEST(StudyResume, AnOxidizedAsperityRefusesTheStateOfAnotherStudyNamingTheEntry) {
  Capture junction;
  run_sheared_junction(coarse_junction(), {}, junction.hooks());
  ASSERT_FALSE(junction.states.empty());
  const auto s = test_support::reduced_oxide_asperity(2 * d0);
  EXPECT_THAT(input_error_of([&] { run_oxide_asperity(s, {}, junction.resume(0.0)); }),
              ::testing::HasSubstr("oxide.tallies"));
}
