// The amorphous sample of §6.2.2: random insertion up to a volume fraction,
// the two-phase relaxation, and the density adjusted afterwards. Material of
// Table 6.4 (d_min = 30, d_c = 150), d0 = 100, a box of 5 d0 (~170 spheres).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "input_error_of.hpp"
#include "wearscale/dem/amorphous_sample.hpp"
#include "wearscale/dem/bonds.hpp"
#include "wearscale/dem/virial_stress.hpp"

using namespace wearscale::dem;

namespace {
CohesiveMaterial table_6_4() { return patch_test_targets(); }

constexpr double d0 = 100.0;

AmorphousSpec small_box(std::uint64_t seed = 1) {
  AmorphousSpec s;
  s.sizes = {d0, 0.75 * d0, 1.25 * d0, 0.2};
  s.box_size = {5 * d0, 5 * d0, 5 * d0};
  s.seed = seed;
  return s;
}

// The smallest centre distance over r_i + r_j among overlapping pairs.
double closest_approach(const Particles& p, const Box& box) {
  double closest = 1.0;
  for_each_close_pair(p, box, 0.0, [&](std::size_t i, std::size_t j, const Vec3& d) {
    closest = std::min(closest, norm(d) / (p.radius[i] + p.radius[j]));
  });
  return closest;
}

Simulation simulation_of(Particles p, const Box& box) {
  return Simulation(std::move(p), box, CohesiveLaw({table_6_4()}), NeighborSettings{0.2 * d0, 0, true});
}
}  // namespace

TEST(AmorphousSample, InsertionReachesTheVolumeFractionWithinHalfAParticle) {
  const auto spec = small_box();
  const auto p = insert_randomly(spec, 1.0);
  const Box box = periodic_box(spec.box_size);
  const double largest = 4.0 / 3.0 * std::numbers::pi * std::pow(0.5 * spec.sizes.largest, 3);
  EXPECT_NEAR(volume_fraction(p, box), 0.75, 0.5 * largest / box.volume());
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(p.position[i][a], box.lo[a]);
      EXPECT_LT(p.position[i][a], box.hi[a]);
    }
    EXPECT_GE(2.0 * p.radius[i], spec.sizes.smallest);
    EXPECT_LE(2.0 * p.radius[i], spec.sizes.largest);
    EXPECT_NEAR(p.mass[i], 4.0 / 3.0 * std::numbers::pi * std::pow(p.radius[i], 3), 1e-9 * p.mass[i]);
  }
}

TEST(AmorphousSample, InsertionIsReproducibleFromItsSeed) {
  const auto a = insert_randomly(small_box(4), 1.0), b = insert_randomly(small_box(4), 1.0),
             c = insert_randomly(small_box(5), 1.0);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.position[i].x, b.position[i].x);
    EXPECT_EQ(a.radius[i], b.radius[i]);
  }
  EXPECT_NE(a.position[0].x, c.position[0].x);
}

TEST(AmorphousSample, RepulsionPhaseSeparatesDeeplyOverlappingParticles) {
  // Random insertion at φ = 0.75 leaves pairs overlapping by more than half
  // their radius sum; 3000 steps of repulsion with c = c_c in the fixed box
  // bring every pair to at least 80 % of r_i + r_j.
  const auto spec = small_box();
  const Box box = periodic_box(spec.box_size);
  auto sim = simulation_of(insert_randomly(spec, 1.0), box);
  EXPECT_LT(closest_approach(sim.particles(), box), 0.5);
  RelaxationSettings phase1_only;
  phase1_only.max_cohesion_steps = 0;
  const auto report = relax_amorphous(sim, phase1_only);
  EXPECT_EQ(report.repulsion_steps, 3000);
  EXPECT_EQ(report.cohesion_steps, 0);
  EXPECT_FALSE(report.converged);
  EXPECT_GT(closest_approach(sim.particles(), sim.box()), 0.8);
  EXPECT_EQ(sim.box().hi.x, box.hi.x);  // the box is fixed in phase 1
  // The law's switches are restored.
  EXPECT_TRUE(sim.law_as<CohesiveLaw>().cohesion);
  EXPECT_TRUE(sim.law_as<CohesiveLaw>().tangential);
}

TEST(AmorphousSample, RelaxationConvergesToZeroNormalStressAndTheTargetDensity) {
  RelaxationSettings settings;
  settings.stress_tolerance = 1e-12;
  const auto spec = small_box();
  const auto sample = make_amorphous_sample(table_6_4(), spec, settings);
  ASSERT_TRUE(sample.relaxation.converged) << sample.relaxation.cohesion_steps << " steps";
  EXPECT_GT(sample.relaxation.cohesion_steps, 100);
  EXPECT_LT(sample.relaxation.cohesion_steps, settings.max_cohesion_steps);
  EXPECT_NEAR(sample.inserted_volume_fraction, 0.75, 0.01);
  EXPECT_NE(sample.box.hi.x, spec.box_size.x);  // the box moved
  EXPECT_DOUBLE_EQ(sample.relaxed_volume_fraction, volume_fraction(sample.particles, sample.box));

  // Density: Σ m / V = ρ.
  double mass = 0.0;
  for (double m : sample.particles.mass) mass += m;
  EXPECT_NEAR(mass / sample.box.volume(), table_6_4().density, 1e-12);

  // At rest, wrapped into the box, and the normal stress of the relaxed
  // sample, measured afresh with cohesion on, is below tol E.
  for (std::size_t i = 0; i < sample.particles.size(); ++i) {
    EXPECT_EQ(norm(sample.particles.velocity[i]), 0.0);
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(sample.particles.position[i][a], sample.box.lo[a]);
      EXPECT_LT(sample.particles.position[i][a], sample.box.hi[a]);
    }
  }
  auto sim = simulation_of(sample.particles, sample.box);
  sim.law_as<CohesiveLaw>().tangential = false;
  sim.set_track_virial(true);
  sim.compute_forces();
  EXPECT_LT(max_normal_stress(box_stress(sim)), 2e-12 * table_6_4().young);
}

TEST(AmorphousSample, ReportsAPhaseTwoThatDidNotConverge) {
  RelaxationSettings settings;
  settings.max_cohesion_steps = 50;
  const auto sample = make_amorphous_sample(table_6_4(), small_box(), settings);
  EXPECT_FALSE(sample.relaxation.converged);
  EXPECT_EQ(sample.relaxation.cohesion_steps, 50);
  EXPECT_GT(max_normal_stress(sample.relaxation.stress), 1e-14 * table_6_4().young);
}

TEST(AmorphousSample, MatchDensityScalesEveryMassByOneFactor) {
  const auto spec = small_box();
  auto p = insert_randomly(spec, 1.0);
  const Box box = periodic_box(spec.box_size);
  const auto before = p.mass;
  match_density(p, box, 2.0);
  double mass = 0.0;
  for (double m : p.mass) mass += m;
  EXPECT_NEAR(mass / box.volume(), 2.0, 1e-12);
  const double factor = p.mass[0] / before[0];
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_NEAR(p.mass[i], factor * before[i], 1e-12 * p.mass[i]);
    EXPECT_NEAR(p.inv_inertia[i], 1.0 / (0.4 * p.mass[i] * p.radius[i] * p.radius[i]), 1e-12 * p.inv_inertia[i]);
  }
  EXPECT_NEAR(factor, 2.0 / volume_fraction(p, box), 1e-12 * factor);  // particle density ρ/φ
}

TEST(AmorphousSample, RelaxationNeedsTheCohesiveLaw) {
  const auto spec = small_box();
  Simulation sim(insert_randomly(spec, 1.0), periodic_box(spec.box_size), HookeLaw{1, 1, 0, 0, 0.5},
                 NeighborSettings{20.0, 0, true});
  EXPECT_NE(input_error_of([&] { relax_amorphous(sim); }).find("cohesive"), std::string::npos);
  EXPECT_NE(input_error_of([&] { insert_randomly(AmorphousSpec{}, 1.0); }).find("box length"), std::string::npos);
}
