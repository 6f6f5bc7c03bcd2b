// Clusters of bonded particles, to detect detached wear particles (§6.3,
// §7.2): separated blobs are separate clusters, touching ones merge, across
// periodic boundaries too, and a cluster knows whether it holds a wall.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "wearscale/dem/clusters.hpp"
#include "wearscale/dem/hcp_lattice.hpp"

using namespace wearscale::dem;

namespace {
// A 2 × 1 × 1-cell HCP blob (8 unit spheres touching) shifted by `at`.
void add_blob(Particles& p, const Vec3& at, int body) {
  const HcpLattice lattice{1.0, 2, 1, 1};
  for (const auto& x : lattice.sites()) p.add({x + at, 0.5, 1.0, {}, 0, body});
}

Box box_of(double size, bool periodic) {
  Box b;
  b.lo = {0, 0, 0};
  b.hi = {size, size, size};
  b.periodic = {periodic, periodic, periodic};
  return b;
}

const BondCriterion touching = BondCriterion::contact(0.01);
constexpr double sphere_volume = std::numbers::pi / 6.0;  // unit diameter
}  // namespace

TEST(Clusters, SeparatedBlobsAreTwoClusters) {
  Particles p;
  add_blob(p, {2, 2, 2}, 1);
  add_blob(p, {2, 10, 2}, 2);
  p.add({{15, 15, 15}, 0.5, 2.0, {}, 0, 3});  // a lone heavier sphere
  const auto c = find_clusters(p, box_of(20, false), touching);
  ASSERT_EQ(c.clusters.size(), 3u);
  EXPECT_EQ(c.clusters[0].size(), 8u);
  EXPECT_EQ(c.clusters[1].size(), 8u);
  EXPECT_EQ(c.clusters[2].size(), 1u);
  EXPECT_EQ(c.clusters[0].bodies, std::vector<int>{1});
  EXPECT_EQ(c.clusters[1].bodies, std::vector<int>{2});
  // Mass, centre and the diameter of the sphere of equal solid volume.
  EXPECT_NEAR(c.clusters[0].mass, 8.0 * sphere_volume, 1e-12);
  EXPECT_NEAR(c.clusters[0].equivalent_diameter, 2.0, 1e-12);  // 8 unit spheres: d_eq = 8^(1/3)
  EXPECT_NEAR(c.clusters[2].mass, 2.0 * sphere_volume, 1e-12);
  EXPECT_NEAR(c.clusters[2].equivalent_diameter, 1.0, 1e-12);
  EXPECT_NEAR(norm(c.clusters[2].center - Vec3{15, 15, 15}), 0.0, 1e-12);
  Vec3 mean{};
  for (std::size_t i : c.clusters[1].members) mean += 0.125 * p.position[i];
  EXPECT_NEAR(norm(c.clusters[1].center - mean), 0.0, 1e-12);
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(c.label[i], i < 8 ? 0u : (i < 16 ? 1u : 2u));
  for (const auto& cl : c.clusters) EXPECT_FALSE(cl.touches_wall());
}

TEST(Clusters, TouchingBlobsMerge) {
  // The second blob one spacing further along x: its first column touches the
  // last column of the first (HCP stacking along x repeats every a).
  Particles p;
  add_blob(p, {2, 2, 2}, 1);
  add_blob(p, {4, 2, 2}, 2);
  const auto c = find_clusters(p, box_of(20, false), touching);
  ASSERT_EQ(c.clusters.size(), 1u);
  EXPECT_EQ(c.clusters[0].size(), 16u);
  EXPECT_EQ(c.clusters[0].bodies, (std::vector<int>{1, 2}));
  // 0.06 further apart (gaps ≥ 0.03 > 0.01), they are two again.
  Particles q;
  add_blob(q, {2, 2, 2}, 1);
  add_blob(q, {4.06, 2, 2}, 2);
  EXPECT_EQ(find_clusters(q, box_of(20, false), touching).clusters.size(), 2u);
}

TEST(Clusters, BlobAcrossAPeriodicBoundaryIsOneWithItsCentreOnTheBoundary) {
  // A blob split by the x boundary: half of it near x = 0, half near x = 20.
  Particles p;
  add_blob(p, {-1.0, 5, 5}, 1);
  for (auto& x : p.position)
    if (x.x < 0.0) x.x += 20.0;
  const auto periodic = find_clusters(p, box_of(20, true), touching);
  ASSERT_EQ(periodic.clusters.size(), 1u);
  // Unwrapped, the blob spans x ∈ [−1, 0.5]; its centre −0.25 wraps to 19.75.
  EXPECT_NEAR(periodic.clusters[0].center.x, 19.75, 1e-12);
  // Without periodicity the two halves are apart.
  EXPECT_EQ(find_clusters(p, box_of(20, false), touching).clusters.size(), 2u);
}

TEST(Clusters, ClustersKnowTheirWallsAndAWallIsOneSolid) {
  // A wall of two frozen spheres far apart, a blob touching one of them, and
  // a detached blob: the detached one is the wear particle.
  Particles p;
  add_blob(p, {2, 2, 2}, 1);
  // w0 sits one diameter below the blob's lowest site (2, 2, 2): touching.
  const std::size_t w0 = p.add({{2, 2, 1}, 0.5, 1.0, {}, 0, 9});
  const std::size_t w1 = p.add({{15, 15, 0.5}, 0.5, 1.0, {}, 0, 9});
  add_blob(p, {10, 10, 10}, 1);
  p.wall[w0] = 0;
  p.wall[w1] = 0;
  const auto c = find_clusters(p, box_of(20, false), touching);
  ASSERT_EQ(c.clusters.size(), 2u);
  EXPECT_EQ(c.clusters[0].size(), 10u);  // blob + both wall spheres
  EXPECT_TRUE(c.clusters[0].touches_wall());
  EXPECT_EQ(c.clusters[0].walls, std::vector<int>{0});
  EXPECT_EQ(c.clusters[0].bodies, (std::vector<int>{1, 9}));
  EXPECT_FALSE(c.clusters[1].touches_wall());
  EXPECT_EQ(c.label[w1], 0u);
}
