// Bonded pairs, the base of worn-particle tagging and cluster analysis: the
// cell search finds exactly the pairs a direct O(N²) search over nearest
// periodic images finds, each once, whatever the number of cells.
#include <gtest/gtest.h>

#include <set>
#include <utility>

#include "wearscale/dem/bonds.hpp"
#include "wearscale/dem/random.hpp"

using namespace wearscale::dem;

namespace {
Particles random_spheres(const Box& box, std::size_t n, std::uint64_t seed) {
  Random random(seed);
  Particles p;
  for (std::size_t i = 0; i < n; ++i)
    p.add({{random.uniform(box.lo.x, box.hi.x), random.uniform(box.lo.y, box.hi.y), random.uniform(box.lo.z, box.hi.z)},
           random.uniform(0.4, 0.6), 1.0, {}, 0, 0});
  return p;
}

std::set<std::pair<std::size_t, std::size_t>> direct(const Particles& p, const Box& box, double gap) {
  std::set<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      if (norm(box.minimum_image(p.position[j] - p.position[i])) - p.radius[i] - p.radius[j] <= gap)
        out.emplace(i, j);
  return out;
}
}  // namespace

TEST(Bonds, CellSearchFindsExactlyTheDirectPairs) {
  // Box lengths of 2.6 to 12 cutoffs: one, two and many cells per axis.
  for (const Vec3& size : {Vec3{3.5, 3.5, 3.5}, Vec3{5.0, 7.0, 16.0}, Vec3{16.0, 16.0, 16.0}})
    for (const bool periodic : {true, false}) {
      Box box;
      box.hi = size;
      box.periodic = {periodic, periodic, true};
      const auto p = random_spheres(box, 400, 3);
      const auto pairs = bonded_pairs(p, box, BondCriterion::contact(0.1));
      const std::set<std::pair<std::size_t, std::size_t>> found(pairs.begin(), pairs.end());
      EXPECT_EQ(found.size(), pairs.size()) << "a pair listed twice";
      EXPECT_EQ(found, direct(p, box, 0.1)) << size.x << " " << size.y << " " << size.z << " periodic " << periodic;
      EXPECT_FALSE(pairs.empty());
    }
}

TEST(Bonds, PerPairLimitsAreApplied) {
  // Two pairs at gaps 0.2 and 0.4, a criterion of 0.5 overall but 0.3 for
  // pairs of particles of material 1.
  Box box;
  box.hi = {20, 20, 20};
  Particles p;
  p.add({{5, 5, 5}, 0.5, 1.0, {}, 0, 0});
  p.add({{6.2, 5, 5}, 0.5, 1.0, {}, 0, 0});
  p.add({{5, 10, 5}, 0.5, 1.0, {}, 1, 0});
  p.add({{6.4, 10, 5}, 0.5, 1.0, {}, 1, 0});
  BondCriterion bond;
  bond.max_gap = 0.5;
  bond.gap = [](const Particles& q, std::size_t i, std::size_t) { return q.material[i] == 1 ? 0.3 : 0.5; };
  EXPECT_EQ(bonded_pairs(p, box, bond), (std::vector<std::pair<std::size_t, std::size_t>>{{0, 1}}));
  EXPECT_EQ(bonded_pairs(p, box, BondCriterion::contact(0.5)).size(), 2u);
}
