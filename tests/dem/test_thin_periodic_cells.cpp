// Periodic cells thinner than the neighbour cutoff, down to one particle
// diameter (the 2.4 nm deep cell of §7.1.1): a pair meets several images of
// its neighbour, each its own contact with its own tangential history, and a
// particle may meet its own images, as with LAMMPS' ghost atoms.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "input_error_of.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/dem/hcp_lattice.hpp"
#include "wearscale/dem/simulation.hpp"
#include "shaken_hcp_block.hpp"

using namespace wearscale;
using namespace wearscale::dem;

namespace {

constexpr double r = 20.0;  // d = 40 < d_c = 150 of Table 6.4: δ_f = 30

CohesiveMaterial table_6_4(double restitution) {
  auto m = patch_test_targets();
  m.restitution = restitution;
  return m;
}

// Spheres on an x–z grid (neighbours 42-43 apart), at random heights in a
// cell `depth` thick along y, with random velocities and spins so that pairs
// slide: most pairs meet two or three images of each other across y.
Particles loose_spheres(double depth, std::uint64_t seed, double drift = 0.0) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Particles p;
  for (int ix = 0; ix < 4; ++ix)
    for (int iz = 0; iz < 4; ++iz) {
      const Vec3 x{5.0 + 42.5 * ix + u(rng), depth * u(rng), 5.0 + 42.5 * iz + u(rng)};
      const Vec3 v{0.02 * (u(rng) - 0.5), drift + 0.02 * (u(rng) - 0.5), 0.02 * (u(rng) - 0.5)};
      const std::size_t i = p.add({x, r, 1.0, v, 0, 0});
      p.omega[i] = {1e-3 * (u(rng) - 0.5), 1e-3 * (u(rng) - 0.5), 1e-3 * (u(rng) - 0.5)};
    }
  return p;
}

Box cell(double depth) {
  Box b;
  b.lo = {0, 0, 0};
  b.hi = {170, depth, 170};
  return b;
}

using test_support::critical_step;

// The same particles repeated `copies` times along y in a cell that many
// times deeper: there every pair meets one image of each neighbour only.
Simulation unfolded(const Particles& thin, double depth, int copies, const CohesiveLaw& law, NeighborSettings n) {
  Particles p;
  for (int m = 0; m < copies; ++m)
    for (std::size_t i = 0; i < thin.size(); ++i) {
      const std::size_t k = p.add({thin.position[i] + Vec3{0, m * depth, 0}, thin.radius[i], 1.0, thin.velocity[i], 0, 0});
      p.omega[k] = thin.omega[i];
    }
  return Simulation(std::move(p), cell(copies * depth), law, n);
}

// Unwrapped position (the periodic images crossed undone).
Vec3 unwrapped(const Simulation& s, std::size_t i) {
  const auto& p = s.particles();
  const Vec3 l = s.box().length();
  Vec3 x = p.position[i];
  for (int a = 0; a < 3; ++a) x[a] += p.image[i][static_cast<std::size_t>(a)] * l[a];
  return x;
}

}  // namespace

TEST(ThinPeriodicCells, EveryImageOfANeighbourPushesAsInADirectSumOverImages) {
  // Depth 45: just over one diameter, below the cutoff 2r + δ_f + skin = 72:
  // images up to two periods away, and each sphere within reach of its own.
  const double depth = 45.0;
  const auto m = table_6_4(0.8);
  const CohesiveLaw law({m});
  Simulation sim(loose_spheres(depth, 3), cell(depth), law, NeighborSettings{2.0, 0, true});
  sim.compute_forces();
  const auto& p = sim.particles();
  const std::size_t n = p.size();
  // Direct sum over every pair (i ≤ j) and every image of j within five
  // periods along y (nearest image along x and z, 170 ≫ 72), with the
  // fresh-contact force of (6.2)-(6.5): no sliding distance yet, so the
  // tangential force is the damping, dropped when it exceeds the cap F'_m,T
  // (the thesis' LAMMPS pair style, as gran/hooke/history).
  std::vector<Vec3> force(n), torque(n);
  std::size_t contacts = 0, self_contacts = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n; ++j)
      for (int s = -5; s <= 5; ++s) {
        if (i == j && s <= 0) continue;  // a sphere and its own image: once
        Vec3 d = p.position[j] - p.position[i] + Vec3{0, s * depth, 0};
        d.x -= 170.0 * std::nearbyint(d.x / 170.0);
        d.z -= 170.0 * std::nearbyint(d.z / 170.0);
        const auto pp = cohesive_pair(m, r, r, p.mass[i], p.mass[j]);
        const double dist = norm(d);
        if (dist >= 2 * r + pp.delta_f) continue;
        ++contacts;
        if (i == j) ++self_contacts;
        const Vec3 nrm = d * (1.0 / dist);
        const Vec3 vrel = p.velocity[i] - p.velocity[j] + cross(r * p.omega[i] + r * p.omega[j], nrm);
        const double vn = dot(vrel, nrm);
        Vec3 ft = -pp.c_t * (vrel - vn * nrm);
        if (norm(ft) > tangential_cap(pp, dist - 2 * r)) ft = {};
        const Vec3 f = (normal_force(pp, dist - 2 * r) - pp.c_n * vn) * nrm + ft;
        force[i] += f;
        force[j] -= f;
        torque[i] += r * cross(nrm, ft);
        torque[j] += r * cross(nrm, ft);
      }
  ASSERT_GT(self_contacts, 0u) << "spheres meet their own images";
  ASSERT_GT(contacts, 2 * n) << "pairs meet several images";
  double scale = 0.0;
  for (const auto& f : force) scale = std::max(scale, norm(f));
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(p.force[i][c], force[i][c], 1e-12 * scale) << "particle " << i;
      EXPECT_NEAR(p.torque[i][c], torque[i][c], 1e-12 * r * scale) << "particle " << i;
    }
  EXPECT_GE(sim.neighbor_list().pairs(), contacts) << "every contact is in the list (with its skin)";
}

TEST(ThinPeriodicCells, AThinCellMovesLikeItsUnfoldedCopies) {
  // The thin cell against five copies of it in a cell five times deeper
  // (where each pair meets one image): the same forces, and the same motion
  // over 600 steps of sliding contacts, list rebuilds every 10 steps and
  // wraps across the thin axis (the cell drifts along it by two periods), so
  // every contact kept its own history.
  const double depth = 45.0;
  const int copies = 5;
  const CohesiveLaw law({table_6_4(0.7)});
  const NeighborSettings every10{2.0, 10, true};
  const Particles start = loose_spheres(depth, 11, 0.05);
  Simulation thin(start, cell(depth), law, every10);
  Simulation deep = unfolded(start, depth, copies, law, every10);
  const double dt = 0.05 * critical_step(thin);
  thin.set_time_step(dt);
  deep.set_time_step(dt);
  const std::size_t n = start.size();
  double scale = 0.0, slid = 0.0;
  thin.run(600, [&](long) {
    for (std::size_t k = 0; k < thin.neighbor_list().history().size(); ++k)
      slid = std::max(slid, std::fabs(thin.neighbor_list().history()[k]));
  });
  deep.run(600);
  for (std::size_t i = 0; i < n; ++i) scale = std::max(scale, norm(deep.particles().force[i]));
  ASSERT_GT(slid, 0.0) << "the contacts slid";
  ASSERT_GT(thin.neighbor_list().builds(), 50);
  int wrapped = 0;
  for (std::size_t i = 0; i < n; ++i) wrapped += thin.particles().image[i][1] != 0;
  EXPECT_GT(wrapped, 0) << "spheres crossed the thin axis";
  for (int m = 0; m < copies; ++m)
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t k = i + static_cast<std::size_t>(m) * n;
      const Vec3 moved = unwrapped(deep, k) - Vec3{0, m * depth, 0} - unwrapped(thin, i);
      EXPECT_LT(norm(moved), 1e-9 * r) << "particle " << i << " copy " << m;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(deep.particles().force[k][c], thin.particles().force[i][c], 1e-7 * scale)
            << "particle " << i << " copy " << m;
    }
}

namespace {
// A periodic HCP block of touching spheres one diameter long in x (each
// sphere's nearest neighbours along x are its own images) and one HCP cell
// (two close-packed layers) deep in z (a sphere meets the same three spheres
// of the other layer above and below), shaken by random velocities.
Simulation thin_block(double restitution, double step_fraction) {
  return test_support::shaken_hcp_block(1, 3, 1, table_6_4(restitution), step_fraction, 5);
}
}  // namespace

TEST(ThinPeriodicCells, AOneDiameterBlockKeepsTwelveContactsAndConservesMomentum) {
  auto sim = thin_block(0.5, 0.1);
  const Vec3 before = sim.momentum();
  double scale = 0.0;
  for (std::size_t i = 0; i < sim.particles().size(); ++i)
    scale += sim.particles().mass[i] * norm(sim.particles().velocity[i]);
  sim.run(2000);
  EXPECT_EQ(sim.neighbor_list().pairs(), 6u * sim.particles().size()) << "12 bonded contacts each, images included";
  const Vec3 after = sim.momentum();
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(after[c], before[c], 1e-12 * scale);
}

TEST(ThinPeriodicCells, AOneDiameterBlockConservesEnergyWithoutDamping) {
  auto sim = thin_block(1.0, 0.05);
  sim.compute_forces();
  const double e0 = sim.kinetic_energy() + sim.potential_energy();
  const double shaking = e0 - sim.potential_energy();
  double worst = 0.0;
  sim.run(3000, [&](long) { worst = std::max(worst, std::fabs(sim.kinetic_energy() + sim.potential_energy() - e0)); });
  EXPECT_LT(worst, 0.015 * shaking);  // as in the deep block (PairDynamics.EnergyIsConservedWithoutDamping)
}

TEST(ThinPeriodicCells, AResumedThinCellContinuesBitForBit) {
  const double depth = 45.0;
  const CohesiveLaw law({table_6_4(0.7)});
  const NeighborSettings every10{2.0, 10, true};
  auto make = [&] {
    Simulation s(loose_spheres(depth, 11, 0.05), cell(depth), law, every10);
    s.set_time_step(0.05 * critical_step(s));
    return s;
  };
  Simulation straight = make();
  straight.run(400);
  Simulation first = make();
  first.run(235);
  CheckpointState saved;
  first.save_state(saved);
  Simulation resumed = make();
  resumed.restore_state(saved);
  resumed.run(165);
  for (std::size_t i = 0; i < straight.particles().size(); ++i)
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(straight.particles().position[i][c], resumed.particles().position[i][c]) << i;
      ASSERT_EQ(straight.particles().omega[i][c], resumed.particles().omega[i][c]) << i;
    }
  EXPECT_EQ(straight.neighbor_list().history(), resumed.neighbor_list().history());
}

TEST(ThinPeriodicCells, ACellThinnerThanAParticleIsRefused) {
  const CohesiveLaw law({table_6_4(0.9)});
  Simulation sim(loose_spheres(39.0, 1), cell(39.0), law, NeighborSettings{2.0, 0, true});
  EXPECT_THAT(input_error_of([&] { sim.compute_forces(); }),
              testing::AllOf(testing::HasSubstr("along y is 39"), testing::HasSubstr("overlap its own image"),
                             testing::HasSubstr("≥ 40")));
}
