// Worn-particle tagging of §7.2: a particle that has lost more than half of
// its initial interacting neighbours is worn. Hand-made arrangements.
#include <gtest/gtest.h>

#include "wearscale/dem/worn_particles.hpp"
#include "pair_setup.hpp"

using namespace wearscale::dem;
using wearscale::dem::test_support::open_box;

namespace {
// A centre sphere touching four others along ±x, ±y (unit diameters); the
// outer ones are √2 − 1 apart, not bonded to each other.
Particles star() {
  Particles p;
  p.add({{0, 0, 0}, 0.5, 1.0, {}, 0, 0});
  for (const Vec3& x : {Vec3{1, 0, 0}, Vec3{-1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, -1, 0}}) p.add({x, 0.5, 1.0, {}, 0, 0});
  return p;
}

const BondCriterion touching = BondCriterion::contact(0.1);
}  // namespace

TEST(WornParticles, RecordsTheInitialBondedNeighbours) {
  const auto p = star();
  const WornParticles tags(p, open_box(10), touching);
  EXPECT_EQ(tags.initial_neighbors(p.id[0]), 4u);
  for (std::size_t i = 1; i < 5; ++i) EXPECT_EQ(tags.initial_neighbors(p.id[i]), 1u);
  EXPECT_EQ(tags.initial_neighbors(12345), 0u);
  EXPECT_EQ(tags.count_worn(p, open_box(10)), 0u);
}

TEST(WornParticles, WornOnlyWhenMoreThanHalfAreLost) {
  auto p = star();
  const WornParticles tags(p, open_box(10), touching);
  p.position[1].x = 3.0;  // +x leaves: the centre lost 1 of 4, +x lost its only one
  auto lost = tags.lost_fraction(p, open_box(10));
  EXPECT_DOUBLE_EQ(lost[0], 0.25);
  EXPECT_DOUBLE_EQ(lost[1], 1.0);
  auto worn = tags.worn(p, open_box(10));
  EXPECT_FALSE(worn[0]);
  EXPECT_TRUE(worn[1]);
  p.position[2].x = -3.0;  // −x leaves: exactly half lost, not more
  EXPECT_DOUBLE_EQ(tags.lost_fraction(p, open_box(10))[0], 0.5);
  EXPECT_FALSE(tags.worn(p, open_box(10))[0]);
  p.position[3].y = 3.0;  // three of four lost
  EXPECT_TRUE(tags.worn(p, open_box(10))[0]);
  EXPECT_EQ(tags.count_worn(p, open_box(10)), 4u);  // centre, +x, −x, +y; −y kept its bond
}

TEST(WornParticles, FollowsParticlesByIdentityAcrossRemovalAndInsertion) {
  auto p = star();
  const WornParticles tags(p, open_box(10), touching);
  // Remove −y (a lost neighbour of the centre), then add a new sphere
  // touching the centre: it is not one of its initial neighbours.
  p.remove_if([](std::size_t i) { return i == 4; });
  p.add({{0, 0, 1}, 0.5, 1.0, {}, 0, 0});
  const auto lost = tags.lost_fraction(p, open_box(10));
  ASSERT_EQ(lost.size(), 5u);
  EXPECT_DOUBLE_EQ(lost[0], 0.25);
  EXPECT_DOUBLE_EQ(lost[4], 0.0);  // the newcomer had no reference neighbours
  // The centre's index changes; its identity does not.
  p.remove_if([](std::size_t i) { return i == 0; });
  p.add({{0, 0, 0}, 0.5, 1.0, {}, 0, 0});
  const auto after = tags.lost_fraction(p, open_box(10));
  for (double f : after) EXPECT_LE(f, 1.0);
  EXPECT_DOUBLE_EQ(after[0], 1.0);  // +x: its only initial neighbour (old centre) is gone
}

TEST(WornParticles, CohesiveNeighboursAreThoseWithinDeltaF) {
  // Table 6.4 spheres of d = 100: δ_f = 4γ/σ_m,N = 30. Gaps of 25 and 35.
  CohesiveMaterial m = patch_test_targets();
  const CohesiveLaw law({m});
  Box box;
  box.lo = {0, 0, 0};
  box.hi = {1000, 1000, 1000};
  Particles p;
  p.add({{500, 500, 500}, 50, 1.0, {}, 0, 0});
  p.add({{625, 500, 500}, 50, 1.0, {}, 0, 0});
  p.add({{365, 500, 500}, 50, 1.0, {}, 0, 0});
  p.add({{500, 500, 990}, 50, 1.0, {}, 0, 0});  // and one across the periodic z boundary
  p.add({{500, 500, 115}, 50, 1.0, {}, 0, 0});  // gap 1000 − 990 + 115 − 100 = 25
  const WornParticles tags(p, box, BondCriterion::cohesive(law, 50.0));
  EXPECT_EQ(tags.initial_neighbors(p.id[0]), 1u);
  EXPECT_EQ(tags.initial_neighbors(p.id[2]), 0u);
  EXPECT_EQ(tags.initial_neighbors(p.id[3]), 1u);
  EXPECT_EQ(tags.initial_neighbors(p.id[4]), 1u);
}
