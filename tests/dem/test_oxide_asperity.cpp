// The oxidized asperity of §9.3.3 (Fig. 9.26), reduced: the thesis' geometry
// (150 × 150 nm periodic, a 5 nm SiO2 layer on HCP Si, a loose SiO2 cylinder
// of D = 50 nm, a rigid SiO2 plate pressed at 100 MPa) with d0 = 6 nm instead
// of 1.5 nm (about 64 times fewer particles: 5 800), the cell 95 nm high
// instead of 75 (at d0 = 6 nm the plate, the clearances and the Si wall need
// the room), slid 60 nm at 50 m/s (thesis: 10 m/s) after 1 nm of loading.
// The Si/SiO2 pairs take the case's adhesion energy, 0.5 J/m² (the thesis
// does not give its Si–SiO2 coefficients; docs/dem.md).
// What §9.3.3 describes, as facts of this run:
//  - the cylinder rolls: its rotation about y times its radius is its travel
//    (within 20 %; measured 1.07), it travels half the plate's slide (within
//    20 %), and its top keeps up with the plate (travel + θR = slide within
//    5 %), as a body rolling between a fixed surface and the plate does (a
//    body sliding on the layer would turn by nothing, one dragged by the
//    plate would travel the whole slide);
//  - it grows by taking layer particles: at least 5 % of its own count move
//    with it at the end (measured 114 of 1 383: 8 %), and it ends that much
//    larger;
//  - it reaches the Si under the layer, leaving a trench (Fig. 9.26c): the
//    strip it has passed is on average more than half the layer below the
//    surface before sliding (measured 6.7 of 7.8 nm), its deepest point within
//    d0/4 of the Si.
// And the contrast that makes the interface matter: with Si/SiO2 pairs as
// strong in adhesion as mix() makes them (√(γ_Si γ_SiO2) = 1.34 J/m², near
// SiO2's own 1.5) the same cylinder rolls the same way but the layer stays on
// the Si: under 3 % of the body picked up (measured 20), no Si reached.
#include <gtest/gtest.h>

#include <cmath>

#include "reduced_oxide_asperity.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/dem/oxide_asperity.hpp"

using namespace wearscale;
using namespace wearscale::dem;

namespace {
constexpr double d0 = test_support::reduced_oxide_d0;

OxideAsperitySpec reduced() { return test_support::reduced_oxide_asperity(60e-9); }
}  // namespace

TEST(OxideAsperity, TheCylinderRollsGrowsFromTheLayerAndLeavesATrench) {
  const auto spec = reduced();
  const auto r = run_oxide_asperity(spec);
  const double radius = 0.5 * spec.body_diameter;
  const double slide = r.history.back().sliding;

  ASSERT_GT(r.body_particles, 1000u) << "the cylinder is made of many DEM particles";
  ASSERT_GT(r.layer_particles, 300u);
  EXPECT_NEAR(slide, spec.sliding_distance, 0.01 * spec.sliding_distance);
  // The plate holds the load: mean F_N over the second half within 15 % of p A.
  EXPECT_NEAR(r.mean_normal_force, spec.pressure * r.box.x * r.box.y, 0.15 * spec.pressure * r.box.x * r.box.y);
  EXPECT_GT(r.mean_tangential_force, 0.0);

  // It rolls, with the plate (rotation > 0 about y), without slip.
  EXPECT_GT(r.rotation, 0.0);
  EXPECT_NEAR(r.rolling_ratio, 1.0, 0.2) << "rotation " << r.rotation << " rad, travel " << r.travel;
  EXPECT_NEAR(r.travel / slide, 0.5, 0.1);
  // No slip under the plate: the body's top moves with it (travel + θR = slide, within 5 %).
  EXPECT_NEAR((r.travel + r.rotation * radius) / slide, 1.0, 0.05);

  // It grows by taking particles from the layer.
  const double cylinder = static_cast<double>(r.body_particles);
  EXPECT_GE(r.final_picked_up, 0.05 * cylinder);
  EXPECT_GE(r.final_body, 1.04 * cylinder);

  // It peels the layer off the Si behind it: a trench to the Si (Fig. 9.26c).
  EXPECT_GT(r.trench_depth, 0.5 * r.layer_measured) << "surface before sliding " << r.surface_height;
  EXPECT_GE(r.trench_max_depth, r.trench_depth);
  EXPECT_GT(r.trench_max_depth, r.layer_measured - 0.25 * d0);
  EXPECT_GT(r.reached_substrate_at, 0.0);
  EXPECT_LT(r.reached_substrate_at, slide);

  // The history: the first row before loading, the body tracked along the slide.
  EXPECT_EQ(r.history.front().time, 0.0);
  EXPECT_GT(r.history.size(), 50u);
}

TEST(OxideAsperity, AnInterfaceAsStrongAsTheOxideKeepsTheLayerOnTheSi) {
  const auto spec = test_support::reduced_oxide_asperity(60e-9, std::nullopt);  // mix(): 1.34 J/m²
  ASSERT_FALSE(spec.interface.has_value());
  const auto r = run_oxide_asperity(spec);
  EXPECT_NEAR(r.rolling_ratio, 1.0, 0.2) << "rotation " << r.rotation << " rad, travel " << r.travel;
  EXPECT_LT(r.final_picked_up, 0.03 * static_cast<double>(r.body_particles));
  EXPECT_LT(r.trench_max_depth, r.layer_measured - 0.25 * d0);
  EXPECT_LT(r.reached_substrate_at, 0.0);
}

TEST(OxideAsperity, RefusesACellTooLowForItsParts) {
  auto spec = reduced();
  spec.box.z = 75e-9;  // at d0 = 6 nm: no room left for the Si under the layer, cylinder and plate
  EXPECT_THROW(run_oxide_asperity(spec), InputError);
  spec = reduced();
  spec.body_diameter = 2 * d0;
  EXPECT_THROW(run_oxide_asperity(spec), InputError);
}
