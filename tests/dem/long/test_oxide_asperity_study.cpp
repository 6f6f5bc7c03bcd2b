// The oxidized asperity of §9.3.3 (Fig. 9.26) at the thesis' size: 150 × 150
// × 75 nm³, d0 = 1.5 nm (309 165 particles), a 5 nm SiO2 layer on HCP
// Si, a loose SiO2 cylinder of 50 nm, a rigid SiO2 plate at 100 MPa, the
// SiO2/Si pairs at the case's adhesion energy of 0.5 J/m² (docs/dem.md: with
// mix()'s 1.34 J/m² the layer stays on the Si). Label long; slid 100 nm at
// 50 m/s instead of the case's 10 m/s to shorten the run (§7.2.2: no effect
// of v; the d0 = 6 nm runs agree), 82 658 steps. What Fig. 9.26 shows: the
// cylinder rolls, grows by taking layer particles, and reaches the Si,
// leaving a trench. Its spec run to its end through the CLI (6 Dec, 1 h 11 min
// of two threads, 898 MB): θR/travel = 0.97, 13 087 particles taken (11.8 %),
// the body 11.6 % larger, the passed strip bare down to the Si (5.57 nm), the
// Si reached at 26.2 nm (docs/dem.md).
#include <gtest/gtest.h>

#include <cstdio>

#include "wearscale/dem/oxide_asperity.hpp"
#include "wearscale/materials/material.hpp"

using namespace wearscale;
using namespace wearscale::dem;

TEST(OxideAsperityStudy, TheCylinderRollsGrowsAndDigsATrenchToTheSi) {
  OxideAsperitySpec s;
  s.oxide = cohesive_material(materials::silica(), 0.5);
  s.substrate = cohesive_material(materials::silicon(), 0.5, 0.9);
  s.substrate.poisson = 0.2;  // as the case
  s.d0 = 1.5e-9;
  s.box = {150e-9, 150e-9, 75e-9};
  s.interface = mix(s.oxide, s.substrate);
  s.interface->surface_energy = 0.5;  // as the case
  s.velocity = 50.0;
  s.sliding_distance = 100e-9;
  s.settle_distance = 3e-9;
  s.record_every = 1000;
  const auto r = run_oxide_asperity(s);
  std::printf("measured: %zu particles, %ld steps, rotation %.3f rad, travel %.3g nm, rolling ratio %.3f, body %zu -> %.0f "
              "(%.0f picked up), trench %.3g nm (deepest %.3g, layer %.3g), Si reached at %.3g nm, mu %.3f\n",
              r.particles, r.steps, r.rotation, r.travel * 1e9, r.rolling_ratio, r.body_particles, r.final_body,
              r.final_picked_up, r.trench_depth * 1e9, r.trench_max_depth * 1e9, r.layer_measured * 1e9,
              r.reached_substrate_at * 1e9, r.friction);
  EXPECT_NEAR(r.rolling_ratio, 1.0, 0.2);
  const double cylinder = static_cast<double>(r.body_particles);
  EXPECT_GE(r.final_body, 1.04 * cylinder) << "it grows";
  EXPECT_GE(r.final_picked_up, 0.05 * cylinder) << "by taking particles from the layer";
  EXPECT_GT(r.trench_depth, 0.5 * r.layer_measured) << "a trench through the layer along the path";
  EXPECT_GE(r.reached_substrate_at, 0.0) << "Fig. 9.26c: the wear particle reaches the Si under the layer";
}
