// Numbering particles along the cells: a permutation that puts neighbours
// close in index, and a renumbering that carries every particle's data along.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "wearscale/dem/cell_order.hpp"
#include "wearscale/dem/hcp_lattice.hpp"
#include "wearscale/dem/particles.hpp"

using namespace wearscale::dem;

namespace {
Particles shuffled_lattice(int n) {
  HcpLattice lattice{1.0, n, n, n};
  auto sites = lattice.sites();
  std::shuffle(sites.begin(), sites.end(), std::mt19937_64(7));
  Particles p;
  for (std::size_t k = 0; k < sites.size(); ++k) p.add({sites[k], 0.5, 1.0, {double(k), 0, 0}, int(k % 3), int(k)});
  return p;
}
}  // namespace

TEST(CellOrder, IsAPermutationRunningThroughTheCellsLayerByLayer) {
  const Particles p = shuffled_lattice(6);
  const double cell = 1.5;
  const auto order = cell_order(p.position, cell);
  ASSERT_EQ(order.size(), p.size());
  std::vector<std::size_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 0; k < sorted.size(); ++k) ASSERT_EQ(sorted[k], k);
  double z_lo = 1e300, y_lo = 1e300, x_lo = 1e300;
  for (const auto& x : p.position) z_lo = std::min(z_lo, x.z), y_lo = std::min(y_lo, x.y), x_lo = std::min(x_lo, x.x);
  auto layer = [&](std::size_t i) { return std::floor((p.position[i].z - z_lo) / cell); };
  auto row = [&](std::size_t i) { return std::floor((p.position[i].y - y_lo) / cell); };
  for (std::size_t k = 1; k < order.size(); ++k) {
    ASSERT_LE(layer(order[k - 1]), layer(order[k]));
    if (layer(order[k - 1]) == layer(order[k])) {
      ASSERT_LE(row(order[k - 1]), row(order[k]));
    }
  }
}

TEST(CellOrder, RenumberingCarriesEachParticlesStateAndTagsAlong) {
  Particles p = shuffled_lattice(3);
  const Particles before = p;
  const auto order = cell_order(p.position, 1.2);
  p.reorder(order);
  for (std::size_t k = 0; k < p.size(); ++k) {
    const std::size_t i = order[k];
    EXPECT_EQ(p.id[k], before.id[i]);
    EXPECT_EQ(p.position[k].x, before.position[i].x);
    EXPECT_EQ(p.velocity[k].x, before.velocity[i].x);  // the velocity was the insertion index
    EXPECT_EQ(p.body[k], before.body[i]);
    EXPECT_EQ(p.material[k], before.material[i]);
    EXPECT_EQ(p.mass[k], before.mass[i]);
  }
}

TEST(CellOrder, ARenumberingThatIsNotAPermutationIsRefusedAndChangesNothing) {
  Particles p = shuffled_lattice(2);
  const auto ids = p.id;
  std::vector<std::size_t> twice(p.size(), 0);
  EXPECT_THROW(p.reorder(twice), std::invalid_argument);
  std::vector<std::size_t> short_one(p.size() - 1);
  EXPECT_THROW(p.reorder(short_one), std::invalid_argument);
  EXPECT_EQ(p.id, ids);
  EXPECT_THROW(cell_order(p.position, 0.0), std::invalid_argument);
}
