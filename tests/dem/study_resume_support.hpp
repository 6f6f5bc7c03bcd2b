#pragma once
// What the resume tests of the DEM studies share, on either engine: the
// states a run offers (kept, the run going on as the uninterrupted
// reference), a coarse sliding cell, and two histories compared bit for bit.
#include <gtest/gtest.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "captured_states.hpp"
#include "wearscale/dem/cohesive_material.hpp"
#include "wearscale/dem/run_checkpoints.hpp"
#include "wearscale/dem/sliding_cell.hpp"
#include "wearscale/dem/trapped_particles.hpp"
#include "wearscale/materials/material.hpp"

namespace wearscale::dem::test_support {

/// SiO2 (Table 6.5, s = ½) at d0: a few hundred particles, slid 2 d0 at 100 m/s
/// under 0.5 GPa, the checkpoints falling after sliding starts.
inline SlidingCellSpec coarse_cell(double d0, const std::string& engine = "wearscale") {
  SlidingCellSpec c;
  c.material = cohesive_material(materials::silica(), 0.5);
  c.d0 = d0;
  c.velocity = 100.0;
  c.pressure = 0.5e9;
  c.sliding_distance = 2 * d0;
  c.settle_distance = 0.5 * d0;
  c.engine = engine;
  return c;
}

inline void expect_same_history(const std::vector<SlidingSample>& a, const std::vector<SlidingSample>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].time, b[k].time) << "sample " << k;
    EXPECT_EQ(a[k].tangential_force, b[k].tangential_force) << "sample " << k;
    EXPECT_EQ(a[k].normal_force, b[k].normal_force) << "sample " << k;
    EXPECT_EQ(a[k].kinetic_energy, b[k].kinetic_energy) << "sample " << k;
    EXPECT_EQ(a[k].worn, b[k].worn) << "sample " << k;
    EXPECT_EQ(a[k].roughness_bottom, b[k].roughness_bottom) << "sample " << k;
    EXPECT_EQ(a[k].roughness_top, b[k].roughness_top) << "sample " << k;
  }
}

/// Two particles of 3.5 d0 trapped in `cell` (its d0 and engine), resumed half
/// way: the history and every result as the run that never stopped.
inline void expect_trapped_particles_resume_bit_for_bit(const SlidingCellSpec& cell) {
  const double d0 = cell.d0;
  TrappedParticlesSpec s;
  s.cell = cell;
  s.count = 2;
  s.diameter = 3.5 * d0;
  s.cell.box = {2 * 3 * s.diameter, 3.5 * d0, s.diameter + 9 * d0};
  Capture capture;
  const auto straight = run_trapped_particles(s, {}, capture.hooks());
  ASSERT_GE(capture.states.size(), 3u);
  const auto resumed = run_trapped_particles(s, {}, capture.resume(0.5));
  expect_same_history(resumed.history, straight.history);
  EXPECT_EQ(resumed.loose_residual, straight.loose_residual);
  EXPECT_EQ(resumed.friction, straight.friction);
  EXPECT_EQ(resumed.worn_first_body, straight.worn_first_body);
  EXPECT_EQ(resumed.band_thickness, straight.band_thickness);
}

}  // namespace wearscale::dem::test_support
