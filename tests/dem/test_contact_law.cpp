// The contact-law sub-model (contact_law.hpp): the registered laws, what each
// declares (history, pull-off distance, critical time step), and a law made
// by name running in a Simulation.
#include <cmath>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <numbers>
#include <omp.h>
#include <vector>

#include "wearscale/core/errors.hpp"
#include "wearscale/dem/anchor_block.hpp"
#include "wearscale/dem/contact_law.hpp"
#include "wearscale/dem/hcp_lattice.hpp"
#include "wearscale/dem/simulation.hpp"
#include "pair_setup.hpp"

using namespace wearscale;
using namespace wearscale::dem;
using wearscale::dem::test_support::open_box;
using wearscale::dem::test_support::sphere_mass;
using ::testing::HasSubstr;

namespace {

CohesiveMaterial table_6_4() {
  auto m = patch_test_targets();
  m.poisson = 0.15;
  return m;
}

}  // namespace

TEST(ContactLaw, TheCohesiveAndTheHookeLawAreRegisteredByName) {
  EXPECT_THAT(contact_law_names(), ::testing::IsSupersetOf({"cohesive", "hooke"}));
  const ContactLawInputs in{{table_6_4()}, 60.0, 0.5};
  EXPECT_EQ(make_contact_law("cohesive", in)->name(), "cohesive");
  EXPECT_EQ(make_contact_law("hooke", in)->name(), "hooke");
  try {
    make_contact_law("hertz", in);
    FAIL() << "an unknown law was made";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("'hertz'"));
    EXPECT_THAT(e.what(), HasSubstr("cohesive, "));
    EXPECT_THAT(e.what(), HasSubstr("hooke"));
  }
}

TEST(ContactLaw, PullOffDistanceIsTheFractureSeparationWithCohesionAndZeroWithout) {
  const auto m = table_6_4();
  CohesiveLaw cohesive({m});
  const double r = 30.0;
  EXPECT_DOUBLE_EQ(cohesive.pull_off_distance(r), fracture_separation(m, 2.0 * r));  // (6.57)
  cohesive.cohesion = false;
  EXPECT_EQ(cohesive.pull_off_distance(r), 0.0);
  EXPECT_EQ(HookeLaw(1.0, 0.5, 0.0, 0.0, 0.5).pull_off_distance(r), 0.0);  // contact only
  EXPECT_EQ(cohesive.history_size(), 3);
}

TEST(ContactLaw, TheHookeLawFromAMaterialHasTheCohesiveLawsSpringsAtTheCaseDiameter) {
  const auto m = table_6_4();
  const double d0 = 60.0, r = 0.5 * d0, mass = sphere_mass(r, m.density);
  const auto law = make_contact_law("hooke", {{m}, d0, 0.3});
  const auto& hooke = dynamic_cast<const HookeLaw&>(*law);
  const CohesivePair p = cohesive_pair(m, r, r, mass, mass);
  EXPECT_DOUBLE_EQ(hooke.k_n, p.k_n);                 // (6.54)
  EXPECT_DOUBLE_EQ(hooke.k_t, p.k_t);                 // (6.55)
  EXPECT_DOUBLE_EQ(hooke.gamma_n, p.c_n / (0.5 * mass));  // c_N = m* γ_N (6.59)
  EXPECT_DOUBLE_EQ(hooke.friction, 0.3);
  // Δt_c = √(2m/k_N) (6.6) of the lightest mobile particle: a wall's lighter one does not count.
  Particles q;
  q.add({{0, 0, 0}, r, m.density, {}, 0, 0});
  q.add({{100, 0, 0}, 0.5 * r, m.density, {}, 0, 0});
  q.wall[1] = 0;
  EXPECT_DOUBLE_EQ(hooke.critical_time_step(q), std::sqrt(2.0 * mass / p.k_n));
}

// Two equal spheres meet head on: a linear spring-dashpot m* δ'' + m* γ δ' +
// k δ = 0 lets them part at δ = 0 with the restitution e = exp(−π ζ/√(1−ζ²)),
// ζ = γ/(2ω0), ω0 = √(k/m*), momentum conserved, no spin.
TEST(ContactLaw, AHookeLawMadeByNameBouncesTwoSpheresWithTheSpringDashpotRestitution) {
  const auto m = table_6_4();
  const double d0 = 60.0, r = 0.5 * d0;
  auto law = make_contact_law("hooke", {{m}, d0, 0.5});
  const auto& hooke = dynamic_cast<const HookeLaw&>(*law);
  const double m_eff = 0.5 * sphere_mass(r, m.density);
  const double omega0 = std::sqrt(hooke.k_n / m_eff), zeta = hooke.gamma_n / (2.0 * omega0);
  const double expected = std::exp(-std::numbers::pi * zeta / std::sqrt(1.0 - zeta * zeta));
  const double v = 1e-4 * d0 * omega0;  // a gentle approach: overlap ~1e-4 d0
  Particles p;
  p.add({{-r - 0.01, 0, 0}, r, m.density, {v, 0, 0}, 0, 0});
  p.add({{r + 0.01, 0, 0}, r, m.density, {-v, 0, 0}, 0, 1});
  Simulation sim(std::move(p), open_box(), std::move(law), NeighborSettings{2.0, 0, true});
  sim.set_time_step(0.2 * sim.stable_time_step());  // 0.02 Δt_c
  sim.run(static_cast<long>(std::ceil(4.0 * std::numbers::pi / omega0 / sim.time_step())));
  const auto& q = sim.particles();
  ASSERT_GT(q.position[1].x - q.position[0].x, 2.0 * r);  // apart again
  EXPECT_NEAR(q.velocity[1].x / v, expected, 0.01 * expected);
  EXPECT_NEAR(q.velocity[0].x + q.velocity[1].x, 0.0, 1e-12 * v);
  EXPECT_EQ(q.omega[0].z, 0.0);
}

TEST(ContactLaw, ASimulationHandsOutItsLawOnlyAsTheClassItIs) {
  Particles p;
  p.add({{0, 0, 0}, 1.0, 1.0, {}, 0, 0});
  Simulation sim(std::move(p), open_box(), HookeLaw(1.0, 0.5, 0.0, 0.0, 0.5), NeighborSettings{0.1, 0, true});
  EXPECT_EQ(sim.law_as<HookeLaw>().k_n, 1.0);
  EXPECT_THROW(sim.law_as<CohesiveLaw>(), InputError);
}

namespace {
// The anchor block (N = 6912: above the threaded loop's threshold) after
// `steps` steps on `threads` threads: forces, torques and positions.
std::vector<double> anchor_state(int threads, long steps) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  auto sim = make_anchor_block({12, 10});
  sim.run(steps);
  omp_set_num_threads(saved);
  std::vector<double> out;
  const auto& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i)
    for (const Vec3* v : {&p.force[i], &p.torque[i], &p.position[i]})
      out.insert(out.end(), {v->x, v->y, v->z});
  return out;
}
}  // namespace

// Threads share the force arrays through two colours of index blocks
// (pair_loop.hpp): the order of the sums is the blocks', not the threads',
// and the forces are those of one thread to rounding.
TEST(ContactLaw, ThreadedPairLoopGivesTheSameBitsOnAnyThreadCountAndOneThreadsForcesToRounding) {
  const auto one = anchor_state(1, 30), two = anchor_state(2, 30), three = anchor_state(3, 30);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_EQ(two, three);
  double largest = 0.0, worst = 0.0;
  for (std::size_t k = 0; k < one.size(); ++k)
    if (k % 9 < 3) {  // the forces
      largest = std::max(largest, std::fabs(one[k]));
      worst = std::max(worst, std::fabs(one[k] - two[k]));
    }
  // Rounding, grown over 30 steps (measured 4e-13); one missed pair would be ~0.4.
  EXPECT_LT(worst, 1e-10 * largest);
}

// A slab five times as long in index as its list reaches gets four blocks,
// not five: with five, one of two threads ran two of the three even blocks
// while the other waited (the pair loop's critical path 3/5 of the pairs
// instead of 1/2).
TEST(ContactLaw, TwoThreadsGetAsManyBlocksOfEachColour) {
  HcpLattice lattice{0.995, 20, 20, 6};
  Particles p;
  for (const auto& x : lattice.sites()) p.add({x, 0.5, 6.0 / std::numbers::pi, {}, 0, 0});
  Box box = lattice.box();
  box.periodic = {true, true, false};
  Simulation sim(std::move(p), box, HookeLaw{2.0e4, 1.0e4, 50.0, 25.0, 0.5}, NeighborSettings{0.1, 10, false});
  sim.set_time_step(5e-4);
  const int saved = omp_get_max_threads();
  omp_set_num_threads(2);
  sim.run(1);
  omp_set_num_threads(saved);
  std::size_t reach = 0;
  const auto& l = sim.neighbor_list();
  for (std::size_t i = 0; i + 1 < l.offsets().size(); ++i)
    for (std::uint32_t k = l.offsets()[i]; k < l.offsets()[i + 1]; ++k) reach = std::max<std::size_t>(reach, l.neighbors()[k] - i);
  ASSERT_EQ(sim.particles().size() / reach, 5u) << "room for five blocks of the list's reach";
  EXPECT_EQ(sim.colour_blocks(), 4u);
}
