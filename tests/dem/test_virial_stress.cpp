// The virial stress of a region (Morante et al. 2006), tension positive: a
// uniformly strained HCP block against the analytic sum over its pairs and
// against the force on a wall, and the kinetic part of a gas.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "wearscale/dem/hcp_lattice.hpp"
#include "wearscale/dem/virial_stress.hpp"

using namespace wearscale::dem;

namespace {
constexpr double d = 1.0;      // sphere diameter
constexpr double k_n = 2.0e4;  // Hooke stiffness

// Every sphere of an ideal HCP block has 12 neighbours at the spacing a with
// Σ n⊗n = 4 I over them, and a volume a³/√2; a pair force F (> 0 repulsive)
// then gives σ = −(N/V) ½ Σ_j a F n⊗n = −2√2 F / a² I.
double hcp_stress(double pair_force, double a) { return -2.0 * std::numbers::sqrt2 * pair_force / (a * a); }

Particles block(const HcpLattice& lattice, double diameter, double density = 1.0) {
  Particles p;
  for (const auto& x : lattice.sites()) p.add({x, 0.5 * diameter, density, {}, 0, 0});
  return p;
}

CohesiveMaterial table_6_4() { return patch_test_targets(); }
}  // namespace

TEST(VirialStress, CompressedHcpBlockMatchesTheSumOverPairs) {
  const HcpLattice lattice{0.99 * d, 4, 3, 3};
  Simulation sim(block(lattice, d), lattice.box(), HookeLaw{k_n, 0.5 * k_n, 0.0, 0.0, 0.5},
                 NeighborSettings{0.1 * d, 0, true});
  sim.set_track_virial(true);
  sim.compute_forces();
  const auto s = box_stress(sim);
  const double expected = hcp_stress(k_n * (d - lattice.spacing), lattice.spacing);
  EXPECT_LT(expected, 0.0);  // compression is negative
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(s[static_cast<std::size_t>(a)], expected, 1e-10 * std::fabs(expected));
  for (int a = 3; a < 6; ++a) EXPECT_NEAR(s[static_cast<std::size_t>(a)], 0.0, 1e-10 * std::fabs(expected));
  EXPECT_NEAR(max_normal_stress(s), std::fabs(expected), 1e-10 * std::fabs(expected));
}

TEST(VirialStress, StretchedCohesiveBlockIsInTension) {
  // Table 6.4 spheres of d = 100 pulled apart by a gap of 5 < δ_e = 20: each
  // pair attracts with k_N δ (6.3) and the stress is +2√2 k_N δ / a².
  const double diameter = 100.0, gap = 5.0;
  const HcpLattice lattice{diameter + gap, 4, 3, 3};
  Simulation sim(block(lattice, diameter), lattice.box(), CohesiveLaw({table_6_4()}),
                 NeighborSettings{10.0, 0, true});
  sim.set_track_virial(true);
  sim.compute_forces();
  const auto pair = cohesive_pair(table_6_4(), 50.0, 50.0, sim.particles().mass[0], sim.particles().mass[0]);
  ASSERT_LT(gap, pair.delta_e);
  const double expected = -hcp_stress(pair.k_n * gap, lattice.spacing);
  EXPECT_GT(expected, 0.0);
  const auto s = box_stress(sim);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(s[static_cast<std::size_t>(a)], expected, 1e-10 * expected);
}

TEST(VirialStress, RegionStressEqualsTheWallForcePerArea) {
  // Periodic in x, y; the lowest and highest layers frozen into walls. The
  // stress of the mobile layers, over the volume they fill, equals the load
  // on the top wall per area: σ_zz = −F_z / A (and the bulk value).
  const HcpLattice lattice{0.99 * d, 4, 3, 3};
  Box box = lattice.box();
  box.periodic = {true, true, false};
  Simulation sim(block(lattice, d), box, HookeLaw{k_n, 0.5 * k_n, 0.0, 0.0, 0.5}, NeighborSettings{0.1 * d, 0, true});
  const double layer = 0.5 * lattice.cell().z;
  std::vector<std::size_t> bottom, top, mobile;
  for (std::size_t i = 0; i < sim.particles().size(); ++i) {
    const double z = sim.particles().position[i].z;
    if (z < 0.5 * layer)
      bottom.push_back(i);
    else if (z > (2 * lattice.nz - 1.5) * layer)
      top.push_back(i);
    else
      mobile.push_back(i);
  }
  ASSERT_EQ(mobile.size(), 4u * 2u * 4u * 3u);  // 4 of the 6 layers
  sim.add_wall(bottom, WallMotion::fixed());
  const int top_wall = sim.add_wall(top, WallMotion::fixed());
  sim.set_track_virial(true);
  sim.compute_forces();
  const double a = lattice.spacing;
  const double volume = static_cast<double>(mobile.size()) * a * a * a / std::numbers::sqrt2;
  const auto s = virial_stress(sim, mobile, volume);
  const double area = box.length().x * box.length().y;
  const double load = sim.wall(top_wall).force.z;  // the sample pushes the top wall up
  EXPECT_GT(load, 0.0);
  EXPECT_NEAR(s[2], -load / area, 1e-10 * load / area);
  EXPECT_NEAR(s[2], hcp_stress(k_n * (d - a), a), 1e-10 * load / area);
  EXPECT_NEAR(s[0], s[2], 1e-10 * load / area);
}

TEST(VirialStress, KineticPartOfAGasIsItsPressure) {
  // Spheres far apart (no contacts): σ = −(1/V) Σ m (v − v̄) ⊗ (v − v̄); a
  // common drift adds nothing.
  Box box;
  box.hi = {40, 40, 40};
  Particles p;
  const Vec3 velocities[4] = {{1, 0, 0}, {-1, 0, 0}, {0, 2, 1}, {0, -2, -1}};
  for (int k = 0; k < 4; ++k) p.add({{5.0 + 10 * k, 20, 20}, 0.5, 1.0, velocities[k], 0, 0});
  auto gas = [&](const Vec3& drift) {
    Particles q = p;
    for (auto& v : q.velocity) v += drift;
    Simulation sim(std::move(q), box, HookeLaw{k_n, 0.5 * k_n, 0.0, 0.0, 0.5}, NeighborSettings{0.1, 0, true});
    sim.set_track_virial(true);
    sim.compute_forces();
    return box_stress(sim);
  };
  const double m = p.mass[0], V = box.volume();
  const auto s = gas({});
  EXPECT_NEAR(s[0], -m * 2.0 / V, 1e-15);
  EXPECT_NEAR(s[1], -m * 8.0 / V, 1e-15);
  EXPECT_NEAR(s[2], -m * 2.0 / V, 1e-15);
  EXPECT_NEAR(s[5], -m * 4.0 / V, 1e-15);  // yz
  EXPECT_NEAR(s[3], 0.0, 1e-15);
  const auto drifted = gas({3.0, -1.0, 0.5});
  for (std::size_t c = 0; c < 6; ++c) EXPECT_NEAR(drifted[c], s[c], 1e-14);
}

TEST(VirialStress, NeedsTheVirialToBeTracked) {
  const HcpLattice lattice{0.99 * d, 4, 3, 3};
  Simulation sim(block(lattice, d), lattice.box(), HookeLaw{k_n, 0.5 * k_n, 0.0, 0.0, 0.5},
                 NeighborSettings{0.1 * d, 0, true});
  sim.compute_forces();
  EXPECT_THROW(box_stress(sim), std::logic_error);
}
