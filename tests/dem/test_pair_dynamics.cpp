// Two-particle dynamics of the cohesive DEM: the force law seen through the
// integrator, restitution (6.29), the critical time step (6.6), momentum.
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <random>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/dem/hcp_lattice.hpp"
#include "wearscale/dem/simulation.hpp"
#include "shaken_hcp_block.hpp"
#include "pair_setup.hpp"

using namespace wearscale;
using namespace wearscale::dem;
using wearscale::dem::test_support::open_box;

namespace {

CohesiveMaterial table_6_4(double restitution = 0.95) {
  auto m = patch_test_targets();
  m.restitution = restitution;
  return m;
}

constexpr double r = 20.0;  // r_i + r_j = 40 < d_c = 150

// Two spheres on the x axis with surface gap `gap`, velocities ±v along x.
Simulation pair(double gap, double v, CohesiveLaw law, Box box = open_box(), Vec3 centre = {}) {
  Particles p;
  p.add({centre + Vec3{-r - 0.5 * gap, 0, 0}, r, 1.0, {v, 0, 0}, 0, 0});
  p.add({centre + Vec3{r + 0.5 * gap, 0, 0}, r, 1.0, {-v, 0, 0}, 0, 1});
  return Simulation(std::move(p), box, std::move(law), NeighborSettings{2.0, 0, true});
}

using test_support::critical_step;

}  // namespace

TEST(PairDynamics, ForceOnAParticleFollowsEquation6_3AtSamplePoints) {
  const CohesiveLaw law({table_6_4()});
  const auto params = cohesive_pair(table_6_4(), r, r, 1.0, 1.0);
  for (double gap : {-1.0, -0.1, 0.0, 2.0, params.delta_e, 10.0, 20.0, 29.0, 31.0}) {
    auto sim = pair(gap, 0.0, law);
    sim.compute_forces();
    // Positive F_N attracts: it pulls particle 0 toward +x.
    EXPECT_NEAR(sim.particles().force[0].x, normal_force(params, gap), 1e-12 * params.k_n * 40.0) << "gap " << gap;
    EXPECT_DOUBLE_EQ(sim.particles().force[1].x, -sim.particles().force[0].x);
    EXPECT_EQ(sim.particles().force[0].y, 0.0);
  }
}

TEST(PairDynamics, HeadOnCollisionRestitutionMatchesEta) {
  // Repulsion only (the derivation of (6.32) neglects the cohesive range).
  for (double eta : {0.95, 0.9}) {
    CohesiveLaw law({table_6_4(eta)});
    law.cohesion = false;
    const double v0 = 0.01;
    auto sim = pair(1.0, v0, law);
    sim.set_time_step(0.005 * critical_step(sim));
    sim.run(200000, {});
    const auto& p = sim.particles();
    ASSERT_GT(p.position[1].x - p.position[0].x, 2 * r) << "the particles separated again";
    const double restitution = (p.velocity[1].x - p.velocity[0].x) / (2.0 * v0);
    EXPECT_NEAR(restitution, eta, 0.01 * eta) << "η = " << eta;  // (6.29)-(6.31): a few %
    // The exact restitution of a linear spring-dashpot with ζ = (1−η)/π.
    const double zeta = (1.0 - eta) / std::numbers::pi;
    EXPECT_NEAR(restitution, std::exp(-std::numbers::pi * zeta / std::sqrt(1.0 - zeta * zeta)), 2e-3);
  }
}

namespace {
// Oscillation energy of an undamped Hookean pair: ½ m v² each + ½ k δ².
double oscillation_energy(const Simulation& s, double k_n) {
  const auto& p = s.particles();
  const double gap = p.position[1].x - p.position[0].x - 2 * r;
  return 0.5 * p.mass[0] * dot(p.velocity[0], p.velocity[0]) + 0.5 * p.mass[1] * dot(p.velocity[1], p.velocity[1]) +
         0.5 * k_n * gap * gap;
}
}  // namespace

TEST(PairDynamics, CriticalTimeStepSeparatesStableFromUnstable) {
  auto m = table_6_4(1.0);  // no damping
  const CohesiveLaw law({m});
  const auto params = cohesive_pair(m, r, r, 1.0, 1.0);
  const double gap0 = 0.02 * params.delta_e;
  // Velocity Verlet on k, m_eff = m/2: stable iff ω Δt < 2, i.e. Δt < √(2m/k_N) (6.6).
  // At exactly Δt_c the two eigenvalues coincide at −1 and the amplitude grows
  // linearly, so the stable side is checked just below it.
  {
    auto sim = pair(gap0, 0.0, law);
    const double dt_c = critical_step(sim);
    EXPECT_NEAR(dt_c, std::sqrt(2.0 * sim.particles().mass[0] / params.k_n), 1e-12 * dt_c);
    sim.set_time_step(0.99 * dt_c);
    const double e0 = oscillation_energy(sim, params.k_n);
    double worst = 0.0;
    sim.run(20000, [&](long) { worst = std::max(worst, oscillation_energy(sim, params.k_n)); });
    EXPECT_LT(worst, 60.0 * e0) << "bounded (Verlet's energy error at ωΔt ≈ 2 is large but bounded)";
  }
  {
    auto sim = pair(gap0, 0.0, law);
    sim.set_time_step(1.05 * critical_step(sim));
    const double e0 = oscillation_energy(sim, params.k_n);
    double grown = 0.0;
    bool reported = false;
    try {
      sim.run(100, [&](long) { grown = std::max(grown, oscillation_energy(sim, params.k_n)); });
    } catch (const NumericalError&) {
      reported = true;  // the blow-up is caught as an unstable step
    }
    EXPECT_GT(grown, 100.0 * e0) << "amplitude × 1.86 per step";
    EXPECT_TRUE(reported) << "a particle jumping further than the skin stops the run";
  }
}

TEST(PairDynamics, UnstableTimeStepIsReportedWithTheParticleAndAFix) {
  auto m = table_6_4(1.0);
  CohesiveLaw law({m});
  law.cohesion = false;
  auto sim = pair(-2.0, 0.0, law);
  sim.set_time_step(3.0 * critical_step(sim));
  try {
    sim.run(200, {});
    FAIL() << "no NumericalError";
  } catch (const NumericalError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.solver(), "dem");
    EXPECT_NE(what.find("particle"), std::string::npos) << what;
    EXPECT_NE(what.find("Δt_c"), std::string::npos) << what;
    // The fix names a stable step: 0.1 Δt_c of this pair (6.6).
    EXPECT_NEAR(sim.stable_time_step(), 0.1 * critical_step(sim), 1e-12 * critical_step(sim));
    EXPECT_NE(what.find(fmt::format("{:.3g} here", 0.1 * critical_step(sim))), std::string::npos) << what;
  }
}

namespace {
// A periodic HCP block of touching spheres (δ_N = 0: no force) shaken by
// random velocities: nearest neighbours bonded, across the periodic faces
// too. d = 100 lies in [d_min, d_c] = [30, 150], so second neighbours (gap
// 41) are beyond δ_f = 30 and the touching lattice is at equilibrium.
Simulation shaken_block(double restitution, double step_fraction) {
  return test_support::shaken_hcp_block(4, 3, 3, table_6_4(restitution), step_fraction, 7);
}
}  // namespace

TEST(PairDynamics, MomentumIsConservedWithoutWallsAndGlobalDamping) {
  auto sim = shaken_block(0.5, 0.1);  // pair damping is a pair force too
  const Vec3 before = sim.momentum();
  double scale = 0.0;
  for (std::size_t i = 0; i < sim.particles().size(); ++i) scale += sim.particles().mass[i] * norm(sim.particles().velocity[i]);
  sim.run(2000, {});
  const Vec3 after = sim.momentum();
  EXPECT_EQ(sim.neighbor_list().pairs(), 6u * sim.particles().size()) << "12 bonded neighbours each";
  EXPECT_NEAR(after.x, before.x, 1e-12 * scale);
  EXPECT_NEAR(after.y, before.y, 1e-12 * scale);
  EXPECT_NEAR(after.z, before.z, 1e-12 * scale);
}

TEST(PairDynamics, EnergyIsConservedWithoutDamping) {
  auto sim = shaken_block(1.0, 0.05);
  sim.compute_forces();
  const double e0 = sim.kinetic_energy() + sim.potential_energy();
  const double bound = sim.potential_energy();  // energy of the bonded lattice at rest
  const double shaking = e0 - bound;
  double worst = 0.0;
  sim.run(3000, [&](long) { worst = std::max(worst, std::fabs(sim.kinetic_energy() + sim.potential_energy() - e0)); });
  // Velocity Verlet's energy error is a bounded O((ωΔt)²) fluctuation:
  // measured 3 % of the shaking energy at 0.1 Δt_c, under 1 % at 0.05 Δt_c.
  EXPECT_LT(worst, 0.015 * shaking);
}

TEST(PairDynamics, PeriodicImagePairFeelsTheSameForceAsADirectPair) {
  const CohesiveLaw law({table_6_4()});
  Box box;
  box.lo = {0, 0, 0};
  box.hi = {300, 300, 300};
  // Direct pair in the middle of the box, sliding against each other.
  Particles direct;
  direct.add({{130, 150, 150}, r, 1.0, {0, 0.01, 0}, 0, 0});
  direct.add({{170.5, 151, 149}, r, 1.0, {0, -0.01, 0.002}, 0, 0});
  // The same pair straddling the periodic boundary in x.
  Particles image = direct;
  image.position[0].x = 280.0;
  image.position[1].x = 280.0 + 40.5 - 300.0;
  Simulation a(std::move(direct), box, law, NeighborSettings{2.0, 0, true});
  Simulation b(std::move(image), box, law, NeighborSettings{2.0, 0, true});
  for (auto* s : {&a, &b}) {
    s->set_time_step(0.05 * critical_step(*s));
    s->run(50, {});
  }
  for (std::size_t i = 0; i < 2; ++i)
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(a.particles().force[i][c], b.particles().force[i][c], 1e-9 * std::fabs(a.particles().force[0].x)) << i << c;
      EXPECT_NEAR(a.particles().torque[i][c], b.particles().torque[i][c], 1e-9 * r * std::fabs(a.particles().force[0].x)) << i << c;
    }
  EXPECT_NE(a.particles().torque[0].z, 0.0) << "the pair slides: tangential force and torque";
}

TEST(PairDynamics, TangentialForceIsCappedAndSurvivesNeighbourRebuilds) {
  // Two bonded spheres sheared past each other: the tangential spring force
  // saturates at F_m,T (6.4) and keeps its history across list rebuilds.
  const auto m = table_6_4(1.0);
  const CohesiveLaw law({m});
  const auto params = cohesive_pair(m, r, r, 1.0, 1.0);
  Particles p;
  p.add({{0, 0, 0}, r, 1.0, {}, 0, 0});
  p.add({{2 * r, 0, 0}, r, 1.0, {}, 0, 1});
  Simulation sim(std::move(p), open_box(), law, NeighborSettings{0.5, 5, false});
  const int lower = sim.add_wall({0}, WallMotion::fixed());
  const int upper = sim.add_wall({1}, WallMotion::moving({0, 1e-3, 0}));
  sim.set_time_step(0.05 * critical_step(sim));
  double peak = 0.0;
  sim.run(2500, [&](long) {
    // The tangential part of the pair force (the normal part tilts with the slide).
    const auto& x = sim.particles().position;
    const Vec3 n = (x[1] - x[0]) * (1.0 / norm(x[1] - x[0]));
    const Vec3 f = sim.wall(upper).force;
    peak = std::max(peak, norm(f - dot(f, n) * n));
  });
  EXPECT_GT(sim.wall(upper).displacement.y, 1.5 * params.f_mt / params.k_t) << "slid past the cap";
  EXPECT_GT(sim.neighbor_list().builds(), 100);
  EXPECT_NEAR(peak, params.f_mt, 0.02 * params.f_mt);
  EXPECT_NEAR(sim.wall(lower).force.y, -sim.wall(upper).force.y, 1e-12);
}
