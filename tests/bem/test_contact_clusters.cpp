// Micro-contacts: connected clusters of a periodic contact map.
#include <gtest/gtest.h>

#include "wearscale/bem/contact_clusters.hpp"

using namespace wearscale;
using namespace wearscale::bem;

namespace {
void square(RealField& p, long i0, long j0, long size) {
  for (long i = i0; i < i0 + size; ++i)
    for (long j = j0; j < j0 + size; ++j) p[p.grid().periodic_index(i, j)] = 1.0;
}
}  // namespace

TEST(ContactClusters, SeparatePatchesAreSeparateClustersLargestFirst) {
  RealField p(Grid2D(32, 32, 2.0, 2.0));
  square(p, 2, 2, 3);
  square(p, 20, 10, 5);
  const auto map = find_clusters(p);
  ASSERT_EQ(map.clusters.size(), 2u);
  EXPECT_EQ(map.clusters[0].points, 25u);
  EXPECT_DOUBLE_EQ(map.clusters[0].area, 25 * p.grid().cell_area());
  EXPECT_DOUBLE_EQ(map.clusters[0].centroid_x, 22 * p.grid().dx());
  EXPECT_DOUBLE_EQ(map.clusters[0].centroid_y, 12 * p.grid().dy());
  EXPECT_EQ(map.clusters[1].points, 9u);
  EXPECT_EQ(map.label[p.grid().index(3, 3)], 1);
  EXPECT_EQ(map.label[p.grid().index(0, 0)], -1);
  EXPECT_DOUBLE_EQ(contact_area(p), 34 * p.grid().cell_area());
}

TEST(ContactClusters, APatchAcrossThePeriodicCornerIsOneClusterCentredOnTheCorner) {
  RealField p(Grid2D(16, 16, 1.0, 1.0));
  square(p, -2, -2, 4);  // points −2..1 in both directions
  const auto map = find_clusters(p);
  ASSERT_EQ(map.clusters.size(), 1u);
  EXPECT_EQ(map.clusters[0].points, 16u);
  const double c = 1.0 - 0.5 * p.grid().dx();  // mean of −2..1 is −0.5 cells
  EXPECT_NEAR(map.clusters[0].centroid_x, c, 1e-12);
  EXPECT_NEAR(map.clusters[0].centroid_y, c, 1e-12);
  EXPECT_FALSE(map.clusters[0].spans_cell);
}

TEST(ContactClusters, AStripeAroundTheCellSpansIt) {
  RealField p(Grid2D(16, 8, 1.0, 1.0));
  for (std::size_t i = 0; i < 16; ++i) p(i, 3) = 1.0;
  const auto map = find_clusters(p);
  ASSERT_EQ(map.clusters.size(), 1u);
  EXPECT_TRUE(map.clusters[0].spans_cell);
}

TEST(ContactClusters, DiagonalNeighboursJoinOnlyWithEightConnectivity) {
  RealField p(Grid2D(8, 8, 1.0, 1.0));
  p(2, 2) = 1.0;
  p(3, 3) = 1.0;
  EXPECT_EQ(find_clusters(p, Connectivity::Four).clusters.size(), 2u);
  EXPECT_EQ(find_clusters(p, Connectivity::Eight).clusters.size(), 1u);
}
