// The cell grid's split of its layers over the threads of a neighbour
// search: runs of consecutive layers that hold about equal particle counts.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "wearscale/dem/cell_grid.hpp"

using namespace wearscale::dem;

namespace {
// 10 × 10 periodic in plane, open along z over [0, 40]: `dense` particles
// below z = 5 (a substrate) and `sparse` ones spread above.
std::vector<Vec3> substrate_under_space(int dense, int sparse) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> x;
  for (int k = 0; k < dense; ++k) x.push_back({10.0 * u(rng), 10.0 * u(rng), 5.0 * u(rng)});
  for (int k = 0; k < sparse; ++k) x.push_back({10.0 * u(rng), 10.0 * u(rng), 5.0 + 35.0 * u(rng)});
  x.push_back({5.0, 5.0, 40.0});  // the top of the open axis
  return x;
}

const Box plane_box{{0.0, 0.0, 0.0}, {10.0, 10.0, 40.0}, {true, true, false}};
}  // namespace

TEST(CellGrid, ThePartsRunThroughEveryLayerOnceInOrder) {
  CellGrid grid;
  grid.build(substrate_under_space(3000, 300), plane_box, 1.0);
  for (int parts : {1, 2, 3, 7}) {
    int end = 0;
    for (int t = 0; t < parts; ++t) {
      const auto [b, e] = grid.layer_range(t, parts);
      EXPECT_EQ(b, end) << parts;
      EXPECT_LE(b, e);
      end = e;
    }
    EXPECT_EQ(end, grid.layers()) << parts;
  }
}

TEST(CellGrid, TwoThreadsSplitADenseSubstrateWhereItsParticlesAreNotHalfwayUp) {
  CellGrid grid;
  grid.build(substrate_under_space(3000, 300), plane_box, 1.0);
  // 3000 of 3301 particles lie in the lowest eighth: half of them lie below
  // z ≈ 2.75 (about the 7 % of the height), so the split is in the lowest
  // eighth of the layers (halfway up it would hand one thread 91 % of them).
  const auto [b, e] = grid.layer_range(0, 2);
  EXPECT_EQ(b, 0);
  EXPECT_GT(e, 0);
  EXPECT_LT(e, grid.layers() / 8 + 1);
  // Spread evenly, the split is halfway (to two layers; an open axis's
  // layers span the particles' extent, here z in [5, 40]).
  CellGrid even;
  even.build(substrate_under_space(0, 4000), plane_box, 1.0);
  EXPECT_NEAR(even.layer_range(0, 2).second, even.layers() / 2, 2);
}
