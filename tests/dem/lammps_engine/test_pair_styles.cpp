// The contact laws as LAMMPS pair styles (wearscale/cohesive, wearscale/hooke)
// give the in-house laws' forces and torques: two particles in every branch of
// (6.3) and of the tangential cap, through both engines.
#include <gtest/gtest.h>

#include <cmath>

#include "wearscale/dem/cohesive_law.hpp"
#include "wearscale/dem/engine.hpp"
#include "wearscale/dem/hooke_law.hpp"
#include "wearscale/dem/lammps_engine.hpp"

using namespace wearscale::dem;

namespace {

// Two unequal spheres of two materials (every pair parameter per pair), gap
// `gap` along a skewed axis, sliding and spinning.
Particles two_spheres(double gap, double sliding) {
  const double ri = 20.0, rj = 23.0;
  const Vec3 axis = Vec3{1.0, 0.3, -0.2} * (1.0 / std::sqrt(1.13));
  Particles p;
  p.add({{0.0, 0.0, 0.0}, ri, 1.0, {0.01, sliding, 0.002}, 0, 0});
  p.add({axis * (ri + rj + gap), rj, 1.3, {-0.004, -0.5 * sliding, 0.001}, 1, 1});
  p.omega[0] = {0.0, 0.0, 2e-4};
  p.omega[1] = {-1e-4, 3e-4, 0.0};
  return p;
}

std::vector<CohesiveMaterial> two_materials() {
  CohesiveMaterial a = patch_test_targets();
  CohesiveMaterial b = a;
  b.name = "b";
  b.young = 1.4;
  b.poisson = 0.1;
  b.tensile_strength = 0.25;
  b.shear_strength = 0.08;
  b.restitution = 0.9;
  return {a, b};
}

Box open_box() {
  Box box;
  box.lo = {-200, -200, -200};
  box.hi = {200, 200, 200};
  box.periodic = {false, false, false};
  return box;
}

std::unique_ptr<Engine> made(const std::string& engine, Particles p, std::unique_ptr<ContactLaw> law) {
  return make_engine(engine, {std::move(p), open_box(), std::move(law), NeighborSettings{2.0, 0, true}});
}

// Every component of force and torque of both particles within `tol` of the
// largest force (torque) component, relative.
void expect_same_forces(const Engine& a, const Engine& b, double tol, const std::string& what) {
  const auto& p = a.particles();
  const auto& q = b.particles();
  double scale_f = 0.0, scale_t = 0.0;
  for (std::size_t i = 0; i < 2; ++i)
    for (int c = 0; c < 3; ++c) {
      scale_f = std::max(scale_f, std::fabs(p.force[i][c]));
      scale_t = std::max(scale_t, std::fabs(p.torque[i][c]));
    }
  for (std::size_t i = 0; i < 2; ++i)
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(q.force[i][c], p.force[i][c], tol * scale_f) << what << ": force " << i << "," << c;
      EXPECT_NEAR(q.torque[i][c], p.torque[i][c], tol * scale_t + 1e-300) << what << ": torque " << i << "," << c;
    }
}

class PairStyles : public testing::Test {
 protected:
  void SetUp() override { register_lammps_engine(); }
};

}  // namespace

TEST_F(PairStyles, CohesiveForceAndTorqueEqualTheInHouseLawInEveryBranch) {
  const auto mixed = mix(two_materials()[0], two_materials()[1]);
  const auto pair = cohesive_pair(mixed, 20.0, 23.0, 1.0 * 4.0 / 3.0 * M_PI * 8000.0, 1.3 * 4.0 / 3.0 * M_PI * 23.0 * 23.0 * 23.0);
  // Compressed, Hookean cohesion, softening, beyond δ_f.
  for (double gap : {-0.5, 0.5 * pair.delta_e, 0.5 * (pair.delta_e + pair.delta_f), 1.1 * pair.delta_f}) {
    auto house = made("wearscale", two_spheres(gap, 0.02), std::make_unique<CohesiveLaw>(two_materials()));
    auto lmp = made("lammps", two_spheres(gap, 0.02), std::make_unique<CohesiveLaw>(two_materials()));
    house->compute_forces();
    lmp->compute_forces();
    expect_same_forces(*house, *lmp, 1e-12, "gap " + std::to_string(gap));
    if (gap < pair.delta_f) {
      EXPECT_GT(std::fabs(house->particles().force[0].x), 0.0) << gap;
    }
  }
}

TEST_F(PairStyles, CohesiveSlidingContactKeepsTheInHouseHistoryStepByStep) {
  // A contact sliding fast enough to reach the cap (6.5): the history
  // integrates, turns into the tangent plane and is stretched back alike.
  for (double sliding : {0.002, 0.2}) {
    auto house = made("wearscale", two_spheres(-0.3, sliding), std::make_unique<CohesiveLaw>(two_materials()));
    auto lmp = made("lammps", two_spheres(-0.3, sliding), std::make_unique<CohesiveLaw>(two_materials()));
    const double dt = 0.1 * house->law().critical_time_step(house->particles());
    house->set_time_step(dt);
    lmp->set_time_step(dt);
    house->run(20);
    lmp->run(20);
    expect_same_forces(*house, *lmp, 1e-12, "sliding " + std::to_string(sliding));
    for (std::size_t i = 0; i < 2; ++i)
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(lmp->particles().position[i][c], house->particles().position[i][c], 1e-12 * 43.0);
  }
}

TEST_F(PairStyles, HookeForceAndTorqueEqualTheInHouseLaw) {
  for (double gap : {-0.8, -0.05}) {
    auto house = made("wearscale", two_spheres(gap, 0.05), std::make_unique<HookeLaw>(2.0, 1.5, 0.3, 0.2, 0.4));
    auto lmp = made("lammps", two_spheres(gap, 0.05), std::make_unique<HookeLaw>(2.0, 1.5, 0.3, 0.2, 0.4));
    const double dt = 0.05;
    house->set_time_step(dt);
    lmp->set_time_step(dt);
    house->compute_forces();
    lmp->compute_forces();
    expect_same_forces(*house, *lmp, 1e-12, "gap " + std::to_string(gap));
    house->run(10);
    lmp->run(10);
    expect_same_forces(*house, *lmp, 1e-12, "after 10 steps, gap " + std::to_string(gap));
  }
}
