// The neighbour list carries each contact's tangential history over a
// rebuild; with NeighborSettings::history_of_touching_pairs_only it carries
// only that of touching pairs, as LAMMPS' fix neigh/history does for the
// thesis' gran/cohesive/history (bench/dem/thesis_lammps/README.md).
#include <gtest/gtest.h>

#include "wearscale/dem/neighbor_list.hpp"

using namespace wearscale::dem;

namespace {

constexpr double r = 1.0, reach = 0.4;

// Particle 0 touches 1 (overlap 0.01) and is stretched into the cohesive
// zone with 2 (gap 0.2 < reach); 1 and 2 are out of reach.
Particles three_particles() {
  Particles p;
  p.add({{0.0, 0.0, 0.0}, r, 1.0, {}, 0, 0});
  p.add({{1.99, 0.0, 0.0}, r, 1.0, {}, 0, 0});
  p.add({{0.0, 2.2, 0.0}, r, 1.0, {}, 0, 0});
  return p;
}

Box open_box() {
  Box b;
  b.lo = {-5.0, -5.0, -5.0};
  b.hi = {5.0, 5.0, 5.0};
  b.periodic = {false, false, false};
  return b;
}

// The history left on each of 0's pairs after a rebuild at rest, every
// history set to 1 before it: {pair with 1, pair with 2}.
std::pair<double, double> after_rebuild(bool touching_only) {
  const Particles p = three_particles();
  NeighborList list;
  list.set_history_of_touching_pairs_only(touching_only);
  list.build(p, open_box(), reach, 0.1, 3);
  EXPECT_EQ(list.pairs(), 2u);
  for (double& h : list.history()) h = 1.0;
  list.build(p, open_box(), reach, 0.1, 3);
  const auto& nb = list.neighbors();
  double with_1 = -1.0, with_2 = -1.0;
  for (std::uint32_t k = list.offsets()[0]; k < list.offsets()[1]; ++k)
    (nb[k] == 1 ? with_1 : with_2) = list.history()[3 * k];
  return {with_1, with_2};
}

}  // namespace

TEST(NeighborList, ARebuildKeepsTheHistoryOfEveryContact) {
  const auto [touching, stretched] = after_rebuild(false);
  EXPECT_EQ(touching, 1.0);
  EXPECT_EQ(stretched, 1.0);
}

TEST(NeighborList, WithTheLammpsTransferARebuildForgetsThePairsBeyondContact) {
  const auto [touching, stretched] = after_rebuild(true);
  EXPECT_EQ(touching, 1.0);
  EXPECT_EQ(stretched, 0.0);
}
