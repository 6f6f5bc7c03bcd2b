// Micro-contacts joined from slabs of rows (one rank here: its one slab is
// joined to itself across the cell's periodic x edge) are find_clusters'.
#include <gtest/gtest.h>

#include <random>

#include "wearscale/bem/contact_clusters.hpp"
#include "wearscale/bem/slab_clusters.hpp"

using namespace wearscale;
using namespace wearscale::bem;

namespace {
void expect_same_clusters(const RealField& p, Connectivity connectivity, bool centroids_of_spanning) {
  const auto whole = find_clusters(p, connectivity).clusters;
  const auto joined = find_clusters_slab(p, 0, p.grid(), connectivity);
  ASSERT_EQ(joined.size(), whole.size());
  for (std::size_t k = 0; k < whole.size(); ++k) {
    EXPECT_EQ(joined[k].points, whole[k].points) << k;
    EXPECT_EQ(joined[k].area, whole[k].area) << k;
    EXPECT_EQ(joined[k].spans_cell, whole[k].spans_cell) << k;
    if (whole[k].spans_cell && !centroids_of_spanning) continue;  // a wrapping cluster's centroid is the search's
    EXPECT_EQ(joined[k].centroid_x, whole[k].centroid_x) << k;    // bit for bit: sums of integers
    EXPECT_EQ(joined[k].centroid_y, whole[k].centroid_y) << k;
  }
}
}  // namespace

TEST(SlabClusters, APatchAcrossBothPeriodicEdgesIsOneClusterWithTheSearchsCentroid) {
  RealField p(Grid2D(12, 10, 1.2, 1.0));
  for (long i = -2; i < 2; ++i)
    for (long j = -3; j < 1; ++j) p[p.grid().periodic_index(i, j)] = 1.0;  // across the corner
  p[p.grid().index(5, 5)] = 1.0;
  p[p.grid().index(6, 6)] = 1.0;  // diagonal to the one before
  expect_same_clusters(p, Connectivity::Four, true);
  expect_same_clusters(p, Connectivity::Eight, true);
  const auto joined = find_clusters_slab(p, 0, p.grid());
  ASSERT_EQ(joined.size(), 3u);
  EXPECT_EQ(joined.front().points, 16u);
  EXPECT_FALSE(joined.front().spans_cell);
}

TEST(SlabClusters, AStripeAroundTheCellSpansItBothWays) {
  for (bool along_x : {true, false}) {
    RealField p(Grid2D(9, 11, 1.0, 1.0));
    for (long k = 0; k < (along_x ? 9 : 11); ++k) p[along_x ? p.grid().index(static_cast<std::size_t>(k), 4) : p.grid().index(4, static_cast<std::size_t>(k))] = 1.0;
    const auto joined = find_clusters_slab(p, 0, p.grid());
    ASSERT_EQ(joined.size(), 1u);
    EXPECT_TRUE(joined.front().spans_cell) << along_x;
    expect_same_clusters(p, Connectivity::Four, false);
  }
}

TEST(SlabClusters, RandomMapsGiveFindClustersClusters) {
  std::mt19937 rng(7);
  for (double fraction : {0.2, 0.45, 0.6}) {
    RealField p(Grid2D(40, 33, 1.0, 0.8));
    std::bernoulli_distribution in(fraction);
    for (double& v : p) v = in(rng) ? 1.0 : 0.0;
    expect_same_clusters(p, Connectivity::Four, false);
    expect_same_clusters(p, Connectivity::Eight, false);
  }
}
