// Particles renumbered in cell order at neighbour builds
// (NeighborSettings::renumber_every): the pairs and their tangential
// histories follow their particles, a pair whose particles swap sides takes
// the mirrored image and the reversed history, and the user's numbering —
// indices, ids, walls, checkpoints — is what every caller sees.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <random>
#include <tuple>

#include "wearscale/core/errors.hpp"
#include "wearscale/dem/anchor_block.hpp"
#include "wearscale/dem/cell_order.hpp"
#include "wearscale/dem/hcp_lattice.hpp"
#include "wearscale/dem/neighbor_list.hpp"
#include "wearscale/dem/simulation.hpp"

using namespace wearscale;
using namespace wearscale::dem;

namespace {

// The anchor block of the LAMMPS benchmark (Hooke law with Coulomb-capped
// tangential history, two frozen walls, the top one moving), numbered at
// random and stirred so that pairs slide, come and go across rebuilds (every
// 10 steps); renumbered at every `renumber_every`-th build (0: never).
// 4 cells³ particles: from 4096 on they are stepped on every thread.
Simulation stirred_shuffled_block(int renumber_every, int cells = 6) {
  Simulation lattice = make_anchor_block({cells, 10});
  Particles p = lattice.particles();
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::shuffle(order.begin(), order.end(), std::mt19937_64(3));
  p.reorder(order);
  std::mt19937 rng(7);
  std::normal_distribution<double> v(0.0, 0.05);
  const double top = lattice.box().hi.z - lattice.box().length().z / 6.0;  // the anchor's walls, two layers each
  const double bottom = lattice.box().lo.z + lattice.box().length().z / 6.0;
  std::vector<std::size_t> low, high;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.position[i].z < bottom) low.push_back(i);
    if (p.position[i].z > top) high.push_back(i);
    p.velocity[i] = {v(rng), v(rng), v(rng)};
  }
  NeighborSettings settings{0.1, 10, false};  // rebuilt every 10 steps
  settings.renumber_every = renumber_every;
  Simulation sim(std::move(p), lattice.box(), HookeLaw{2.0e4, 1.0e4, 50.0, 25.0, 0.5}, settings);
  sim.add_wall(std::move(low), WallMotion::fixed());
  sim.add_wall(std::move(high), WallMotion::moving({0.05, 0.0, 0.0}));  // shears the block
  sim.set_time_step(lattice.time_step());
  return sim;
}

double largest(const std::vector<Vec3>& v) {
  double m = 0.0;
  for (const Vec3& x : v) m = std::max(m, norm(x));
  return m;
}

}  // namespace

TEST(Renumbering, ASortedSystemHasTheForcesAndEnergyOfTheUnsortedOneUpToTheOrderOfTheSums) {
  // One state with sliding contacts (their springs stretched), run on with
  // and without renumbering until the next neighbour build, which renumbers
  // the randomly numbered particles along the cells: most pairs move to
  // other rows, many swap sides (their histories reversed).
  Simulation plain = stirred_shuffled_block(0);
  plain.run(200);
  const auto& h = plain.neighbor_list().history();
  ASSERT_GT(std::count_if(h.begin(), h.end(), [](double x) { return x != 0.0; }), 1000);
  CheckpointState state;
  plain.save_state(state);
  Simulation sorted = stirred_shuffled_block(1);
  sorted.restore_state(state);
  for (int s = 0; s < 100 && sorted.renumberings() == 0; ++s) {
    plain.run(1);
    sorted.run(1);
  }
  ASSERT_EQ(sorted.renumberings(), 1);
  const auto& a = plain.particles();
  const auto& b = sorted.particles();
  ASSERT_EQ(a.id, b.id) << "the user's numbering is kept";
  for (std::size_t i = 0; i < a.size(); ++i)  // the step moved them by the same forces
    for (int c = 0; c < 3; ++c) ASSERT_EQ(a.position[i][c], b.position[i][c]) << "particle " << i;
  // The forces at those positions: the same contacts, the same histories,
  // summed in another order (and a swapped pair's separation rounded from
  // the other side).
  const double f_max = largest(a.force), t_max = largest(a.torque);
  double f_err = 0.0, t_err = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    f_err = std::max(f_err, norm(a.force[i] - b.force[i]));
    t_err = std::max(t_err, norm(a.torque[i] - b.torque[i]));
  }
  std::printf("measured: largest force difference %.3g of the largest force, torque %.3g\n", f_err / f_max,
              t_err / t_max);
  EXPECT_LT(f_err, 1e-12 * f_max);
  EXPECT_LT(t_err, 1e-12 * t_max);
  EXPECT_NEAR(plain.potential_energy(), sorted.potential_energy(), 1e-12 * plain.potential_energy());
  EXPECT_NEAR(plain.kinetic_energy(), sorted.kinetic_energy(), 1e-12 * plain.kinetic_energy());
}

TEST(Renumbering, TheTrajectoryIsTheUnsortedOneUpToRounding) {
  Simulation plain = stirred_shuffled_block(0, 11), sorted = stirred_shuffled_block(1, 11);
  plain.run(300);
  sorted.run(300);
  ASSERT_EQ(sorted.renumberings(), 31);  // at every build, the first included
  const auto& a = plain.particles();
  const auto& b = sorted.particles();
  double drift = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) drift = std::max(drift, norm(a.position[i] - b.position[i]) / a.radius[i]);
  // The rounding of the sums grows in a chaotic flow, but only so far in 300 steps.
  std::printf("measured: %zu particles, largest position difference %.3g radii after 300 steps\n", a.size(), drift);
  EXPECT_LT(drift, 1e-11);
  EXPECT_NEAR(plain.kinetic_energy(), sorted.kinetic_energy(), 1e-11 * plain.kinetic_energy());
  EXPECT_NEAR(plain.potential_energy(), sorted.potential_energy(), 1e-11 * plain.potential_energy());
}

TEST(Renumbering, FromTheFirstBuildTheListIsCloseInIndex) {
  Simulation plain = stirred_shuffled_block(0), sorted = stirred_shuffled_block(10);
  plain.run(1);
  sorted.run(1);
  auto reach = [](const NeighborList& l) {
    std::size_t most = 0;
    for (std::size_t i = 0; i + 1 < l.offsets().size(); ++i)
      for (std::uint32_t k = l.offsets()[i]; k < l.offsets()[i + 1]; ++k)
        most = std::max<std::size_t>(most, l.neighbors()[k] - i);
    return most;
  };
  const std::size_t n = sorted.particles().size();
  EXPECT_EQ(sorted.renumberings(), 1);
  EXPECT_GT(reach(plain.neighbor_list()), n / 2) << "numbered at random";
  EXPECT_LT(reach(sorted.neighbor_list()), n / 4) << "numbered along the cells";
  EXPECT_EQ(plain.neighbor_list().pairs(), sorted.neighbor_list().pairs());
}

TEST(Renumbering, TheCallerKeepsItsIndicesIdsAndWalls) {
  Simulation sim = stirred_shuffled_block(1);
  const Particles before = sim.particles();
  sim.run(50, [&](long) {
    // Inside an observer too: particle i is the one handed in as i.
    const auto& p = sim.particles();
    ASSERT_EQ(p.id, before.id);
  });
  ASSERT_GT(sim.renumberings(), 1);
  const auto& p = sim.particles();
  EXPECT_EQ(p.id, before.id);
  EXPECT_EQ(p.wall, before.wall);
  EXPECT_EQ(p.radius, before.radius);
  // The moving wall's members moved with it by its displacement, each the
  // particle the caller froze.
  const Wall& moving = sim.wall(1);
  for (std::size_t i : moving.members) {
    EXPECT_EQ(p.wall[i], 1);
    EXPECT_NEAR(p.position[i].x, before.position[i].x + moving.displacement.x, 1e-12) << "member " << i;
  }
}

TEST(Renumbering, ARenumberedRunResumesBitForBit) {
  Simulation straight = stirred_shuffled_block(3);
  straight.run(150);
  CheckpointState state;
  straight.save_state(state);
  EXPECT_EQ(state.text("dem.format"), "wearscale-dem-state-3");
  straight.run(150);
  Simulation resumed = stirred_shuffled_block(3);
  resumed.restore_state(state);
  resumed.run(150);
  const auto& a = straight.particles();
  const auto& b = resumed.particles();
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(a.position[i][c], b.position[i][c]) << "particle " << i;
      ASSERT_EQ(a.omega[i][c], b.omega[i][c]) << "particle " << i;
    }
  EXPECT_EQ(straight.neighbor_list().history(), resumed.neighbor_list().history());
}

TEST(Renumbering, ACheckpointOfAnotherNumberingIsRefused) {
  Simulation sim = stirred_shuffled_block(1);
  sim.run(5);
  CheckpointState state;
  sim.save_state(state);
  auto order = state.array("dem.order");
  order[1] = order[0];  // not a permutation
  state.put("dem.order", order);
  Simulation other = stirred_shuffled_block(1);
  EXPECT_THROW(other.restore_state(state), InputError);
}

namespace {
// Each contact by the identity of its particles (the user's numbering) and
// the image of the second seen from the first, with its history.
using Key = std::tuple<std::uint32_t, std::uint32_t, std::array<int, 3>>;
std::map<Key, std::array<double, 3>> contacts(const NeighborList& l, const std::vector<std::uint32_t>& user_of) {
  std::map<Key, std::array<double, 3>> out;
  for (std::uint32_t i = 0; i + 1 < l.offsets().size(); ++i)
    for (std::uint32_t k = l.offsets()[i]; k < l.offsets()[i + 1]; ++k) {
      const std::uint32_t j = l.neighbors()[k];
      const auto s = l.images().shift(l.shifts()[k]);
      const std::array<double, 3> h{l.history()[3 * k], l.history()[3 * k + 1], l.history()[3 * k + 2]};
      const std::uint32_t a = user_of[i], b = user_of[j];
      if (a <= b)
        out[{a, b, s}] = h;
      else
        out[{b, a, {-s[0], -s[1], -s[2]}}] = {-h[0], -h[1], -h[2]};
    }
  return out;
}
}  // namespace

TEST(NeighborList, RenumberedPairsKeepTheirHistoriesAndSidesSwapReversed) {
  // A periodic HCP block one diameter thin along y (pairs meet several
  // images of a neighbour), every pair given its own history.
  HcpLattice lattice{1.0, 4, 1, 4};
  Particles p;
  for (const auto& x : lattice.sites()) p.add({x, 0.5, 1.0, {}, 0, 0});
  const Box box = lattice.box();
  NeighborList list;
  list.build(p, box, 0.0, 0.1, 3);
  for (std::size_t k = 0; k < list.history().size(); ++k) list.history()[k] = 1.0 + static_cast<double>(k);
  std::vector<std::uint32_t> identity(p.size());
  std::iota(identity.begin(), identity.end(), 0u);
  const auto before = contacts(list, identity);
  // A random renumbering: old i becomes new_index[i].
  std::vector<std::uint32_t> new_index = identity;
  std::shuffle(new_index.begin(), new_index.end(), std::mt19937(5));
  std::vector<std::uint32_t> user_of(p.size());
  for (std::uint32_t i = 0; i < p.size(); ++i) user_of[new_index[i]] = i;
  int reversed = 0;
  list.renumber(new_index, [&](double* h) {
    ++reversed;
    for (int c = 0; c < 3; ++c) h[c] = -h[c];
  });
  EXPECT_GT(reversed, 0);
  EXPECT_EQ(contacts(list, user_of), before);
  // Rows in increasing (neighbour, image), each pair under its lower index.
  for (std::size_t i = 0; i + 1 < list.offsets().size(); ++i)
    for (std::uint32_t k = list.offsets()[i]; k < list.offsets()[i + 1]; ++k) {
      EXPECT_GE(list.neighbors()[k], i);
      if (k > list.offsets()[i]) {
        EXPECT_TRUE(list.neighbors()[k - 1] < list.neighbors()[k] ||
                    (list.neighbors()[k - 1] == list.neighbors()[k] && list.shifts()[k - 1] < list.shifts()[k]));
      }
    }
  // The particles renumbered the same way: a rebuild carries every history.
  std::vector<std::size_t> order(p.size());
  for (std::size_t k = 0; k < p.size(); ++k) order[k] = user_of[k];
  p.reorder(order);
  list.build(p, box, 0.0, 0.1, 3);
  EXPECT_EQ(contacts(list, user_of), before);
}
