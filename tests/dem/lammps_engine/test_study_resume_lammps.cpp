// The DEM studies on the LAMMPS engine resume bit for bit: sheared rough
// surfaces (§7.2), trapped particles (§7.3) and the oxidized asperity
// (§9.3.3), each of whose cells is shrink-wrapped along z, continue from a
// state taken mid-run (a LAMMPS restart file and the engine's clocks) to the
// history and results of the run that never stopped, on one rank.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include "../reduced_oxide_asperity.hpp"
#include "../study_resume_support.hpp"
#include "input_error_of.hpp"
#include "wearscale/dem/lammps_engine.hpp"
#include "wearscale/dem/oxide_asperity.hpp"
#include "wearscale/dem/rough_shear.hpp"
#include "wearscale/dem/trapped_particles.hpp"
#include "wearscale/materials/material.hpp"

using namespace wearscale;
using namespace wearscale::dem;

namespace {
constexpr double d0 = 6e-9;  // coarse: a few hundred particles
using test_support::Capture;
using test_support::expect_same_history;
SlidingCellSpec coarse_cell() { return test_support::coarse_cell(d0, "lammps"); }

class StudyResumeLammps : public testing::Test {
 protected:
  void SetUp() override { register_lammps_engine(); }
};

}  // namespace

TEST_F(StudyResumeLammps, ShearedRoughSurfacesResumedMidSlideEndBitForBitAsTheUninterruptedRun) {
  RoughShearSpec s;
  s.cell = coarse_cell();
  s.cell.box = {10 * d0, 3.5 * d0, 10 * d0};
  s.roughness = 0.04;
  Capture capture;
  const auto straight = run_rough_shear(s, {}, capture.hooks());
  ASSERT_GE(capture.states.size(), 3u);
  for (const double at : {0.5, 1.0}) {  // 1.0: in the rigid-fit window (the last fifth of the slide)
    SCOPED_TRACE("resumed " + std::to_string(at) + " of the way");
    const auto resumed = run_rough_shear(s, {}, capture.resume(at));
    expect_same_history(resumed.history, straight.history);
    EXPECT_EQ(resumed.peak_tangential_force, straight.peak_tangential_force);
    EXPECT_EQ(resumed.friction, straight.friction);
    EXPECT_EQ(resumed.worn, straight.worn);
    EXPECT_EQ(resumed.wear_particle, straight.wear_particle);
    EXPECT_EQ(resumed.wear_particle_residual, straight.wear_particle_residual);
    EXPECT_EQ(resumed.regime, straight.regime);
  }
  // A state of the first format (no global damping in it) cannot continue
  // bit for bit: refused, naming the entry.
  CheckpointState first_format = capture.states.back();
  first_format.put_text("lammps.format", "wearscale-lammps-engine-1");
  RunCheckpoints from;
  from.from = &first_format;
  EXPECT_THAT(input_error_of([&] { run_rough_shear(s, {}, from); }), testing::HasSubstr("lammps.format"));
}

TEST_F(StudyResumeLammps, TrappedParticlesResumedMidSlideEndBitForBitAsTheUninterruptedRun) {
  test_support::expect_trapped_particles_resume_bit_for_bit(coarse_cell());
}

// Resumed while sliding: the settling's damping ended before the state was
// taken, and the resumed run slides undamped too.
TEST_F(StudyResumeLammps, TheOxidizedAsperityResumedWhileSlidingEndsBitForBitAsTheUninterruptedRun) {
  auto s = test_support::reduced_oxide_asperity(d0);
  s.engine = "lammps";
  Capture capture;
  const auto straight = run_oxide_asperity(s, {}, capture.hooks());
  ASSERT_GE(capture.states.size(), 5u);
  const auto resumed = run_oxide_asperity(s, {}, capture.resume(0.7));
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
