// The neighbour list carries each contact's tangential history over a
// rebuild; with NeighborSettings::history_of_touching_pairs_only it carries
// only that of touching pairs, as LAMMPS' fix neigh/history does for the
// thesis' gran/cohesive/history (bench/dem/thesis_lammps/README.md).
#include <gtest/gtest.h>
#include <omp.h>

#include <array>
#include <map>
#include <random>
#include <tuple>

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

namespace {

// A contact in unwrapped terms: i, j and the image of j met by i less the
// periods each was wrapped by (what survives a rebuild), with its history.
using ContactKey = std::tuple<std::uint32_t, std::uint32_t, int, int, int>;
std::map<ContactKey, std::array<double, 3>> contacts(const NeighborList& list, const Particles& p) {
  std::map<ContactKey, std::array<double, 3>> out;
  const auto& off = list.offsets();
  for (std::uint32_t i = 0; i + 1 < off.size(); ++i)
    for (std::uint32_t k = off[i]; k < off[i + 1]; ++k) {
      const std::uint32_t j = list.neighbors()[k];
      const auto s = list.images().shift(list.shifts()[k]);
      const ContactKey key{i, j, s[0] - p.image[j][0] + p.image[i][0], s[1] - p.image[j][1] + p.image[i][1],
                           s[2] - p.image[j][2] + p.image[i][2]};
      out[key] = {list.history()[3 * k], list.history()[3 * k + 1], list.history()[3 * k + 2]};
    }
  return out;
}

struct Built {
  std::vector<std::uint32_t> offsets, neighbors;
  std::vector<std::uint8_t> shifts;
  std::vector<double> history;
  bool operator==(const Built&) const = default;
};

// 12 000 randomly placed spheres in a periodic box (enough for the threaded
// build), rebuilt after random moves across the box's faces with skins that
// grow the list by half and shrink it again: every history must land on its
// contact (checked against the contacts by identity), fresh pairs start at
// zero, and the list and its histories are the same bits on any thread count.
Built random_rebuilds(int threads, bool touching_only) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Box box;
  box.lo = {0.0, 0.0, 0.0};
  box.hi = {18.0, 18.0, 18.0};
  box.periodic = {true, true, true};
  Particles p;
  for (int k = 0; k < 12000; ++k)
    p.add({{18.0 * u(rng), 18.0 * u(rng), 18.0 * u(rng)}, 0.45 + 0.1 * u(rng), 1.0, {}, 0, 0});
  NeighborList list;
  list.set_history_of_touching_pairs_only(touching_only);
  list.build(p, box, 0.0, 0.1, 3);
  double next = 1.0;
  for (const double skin : {0.1, 0.3, 0.05, 0.2, 0.2}) {
    for (double& h : list.history()) h = next++;
    const auto before = contacts(list, p);
    for (std::size_t i = 0; i < p.size(); ++i)
      for (int a = 0; a < 3; ++a) {
        p.position[i][a] += 0.6 * (u(rng) - 0.5);
        p.image[i][static_cast<std::size_t>(a)] -= box.wrap(a, p.position[i][a]);
      }
    list.build(p, box, 0.0, skin, 3);
    std::size_t kept = 0;
    for (const auto& [key, h] : contacts(list, p)) {
      const auto old = before.find(key);
      bool carried = old != before.end();
      if (carried && touching_only) {
        const auto [i, j, sx, sy, sz] = key;
        const Vec3 d = p.position[j] - p.position[i] +
                       Vec3{18.0 * (sx + p.image[j][0] - p.image[i][0]), 18.0 * (sy + p.image[j][1] - p.image[i][1]),
                            18.0 * (sz + p.image[j][2] - p.image[i][2])};
        carried = dot(d, d) < (p.radius[i] + p.radius[j]) * (p.radius[i] + p.radius[j]);
      }
      const std::array<double, 3> want = carried ? old->second : std::array<double, 3>{};
      kept += carried ? 1 : 0;
      EXPECT_EQ(h, want) << "pair " << std::get<0>(key) << "-" << std::get<1>(key) << " at skin " << skin;
      if (h != want) break;
    }
    EXPECT_GT(kept, list.pairs() / 10);  // the test moves histories, not only zeros
  }
  omp_set_num_threads(saved);
  return {list.offsets(), list.neighbors(), list.shifts(), list.history()};
}

}  // namespace

TEST(NeighborList, HistoriesMoveInPlaceToTheirContactsOnAnyThreadCount) {
  const Built one = random_rebuilds(1, false);
  EXPECT_EQ(random_rebuilds(2, false), one);
  EXPECT_EQ(random_rebuilds(3, false), one);
}

TEST(NeighborList, WithTheLammpsTransferOnlyTouchingHistoriesMoveOnAnyThreadCount) {
  const Built one = random_rebuilds(1, true);
  EXPECT_EQ(random_rebuilds(2, true), one);
}

namespace {
// Two spheres touching across the periodic face x = 0 of a 10³ box, the
// history of their contact set to 7, then the list rebuilt after `moved_i`
// and `moved_j` periods along x were added to each (positions unchanged once
// wrapped, images changed by as much): the history left on the pair.
double history_after_wraps(int moved_i, int moved_j) {
  Box box;
  box.lo = {0.0, 0.0, 0.0};
  box.hi = {10.0, 10.0, 10.0};
  box.periodic = {true, true, true};
  Particles p;
  p.add({{0.2, 5.0, 5.0}, 0.5, 1.0, {}, 0, 0});
  p.add({{9.21, 5.0, 5.0}, 0.5, 1.0, {}, 0, 0});
  NeighborList list;
  list.build(p, box, 0.0, 0.1, 3);
  EXPECT_EQ(list.pairs(), 1u);
  for (double& h : list.history()) h = 7.0;
  const std::array<int, 2> moved{moved_i, moved_j};
  for (std::size_t i = 0; i < 2; ++i) {
    p.position[i].x += 10.0 * moved[i];
    p.image[i][0] -= box.wrap(0, p.position[i].x);
  }
  list.build(p, box, 0.0, 0.1, 3);
  EXPECT_EQ(list.pairs(), 1u);
  return list.history().at(0);
}
}  // namespace

// The list keeps each particle's image at the last build modulo 256 (3 bytes,
// not 12); the wraps since are exact up to NeighborList::max_wraps − 1 = 127
// periods either way (Simulation refuses more).
TEST(NeighborList, AContactWhoseTwoSpheresWereWrappedTogetherKeepsItsHistoryUpTo127Periods) {
  for (const int k : {1, -1, 100, 127, -127}) EXPECT_EQ(history_after_wraps(k, k), 7.0) << k << " periods";
}

TEST(NeighborList, ASphereWrappedAloneMeetsItsPartnerThroughAnotherImageAndStartsAfresh) {
  for (const int k : {1, -1, 100, 127, -127}) EXPECT_EQ(history_after_wraps(0, k), 0.0) << k << " periods";
}
