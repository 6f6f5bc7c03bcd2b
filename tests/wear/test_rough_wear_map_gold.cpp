// The rough wear map (ch. 5, Fig. 5.6) at a reduced size against the map the
// detachment model gave before its speed-ups (tests/data/wear/rough_map_128.csv,
// provenance in its header): every surface's particles at every pixel — their
// number, wear volume, largest diameter and a fingerprint of their positions —
// and so every region of the map (invalid, plastic, separated up to each
// curve's smoothed maximum, combined past it) are the same.
//
// The reduced map: n = 128 (q_s = n/8 = 16), H = 0.8, q_l = 8, seeds 1 and 2,
// 8 loads p̃_N over 0.01…0.3 and 6 critical diameters d*/L over 0.01…0.2
// (geometric). It goes through both ways of unloading a particle (kernel sums
// and a padded solve) and both ways of computing a self-energy (pairs and the
// autocorrelation by FFT).
//
// WEARSCALE_WRITE_GOLD=<file> writes the map found instead of comparing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "wearscale/wear/rough_wear_map.hpp"
#include "wearscale/wear/wear_curves.hpp"

using namespace wearscale;
using namespace wearscale::wear;

namespace {

RoughWearMapSpec reduced_map() {
  RoughWearMapSpec spec;
  spec.surface.n = 128;
  spec.surface.k_l = 8.0;
  spec.surface.k_s = 16.0;
  spec.seeds = {1, 2};
  for (int l = 0; l < 8; ++l) spec.loads.push_back(0.01 + (0.3 - 0.01) * l / 7.0);
  for (int d = 0; d < 6; ++d) spec.critical_diameters.push_back(0.01 * std::pow(0.2 / 0.01, d / 5.0));
  return spec;
}

// One surface at one pixel.
struct Row {
  int seed = 0, load = 0, dstar = 0;
  long count = 0;
  double volume = 0.0, largest = 0.0, fingerprint = 0.0;
};

// Regions of Fig. 5.6 per pixel: −1 invalid (crossed), 0 plastic (no
// particle on any surface), 1 separated (up to the load of the curve's
// smoothed maximum), 2 combined (past it).
std::vector<int> regions(const RoughWearMap& map) {
  const std::size_t nl = map.spec.loads.size(), nd = map.spec.critical_diameters.size();
  std::vector<int> r(nl * nd);
  for (std::size_t d = 0; d < nd; ++d) {
    const CurveMaximum top = curve_maximum(map, d);
    for (std::size_t l = 0; l < nl; ++l) {
      const auto& p = map.pixel(l, d);
      r[l * nd + d] = !p.valid ? -1 : p.count_mean == 0.0 ? 0 : (top.found && l > top.index ? 2 : 1);
    }
  }
  return r;
}

}  // namespace

TEST(RoughWearMapGold, EverySurfaceDetachesTheSameParticlesAtEveryPixelAsBeforeTheSpeedUps) {
  const RoughWearMapSpec spec = reduced_map();
  const std::size_t nl = spec.loads.size(), nd = spec.critical_diameters.size();
  std::vector<SurfaceWearMap> surfaces;
  std::vector<Row> found;
  for (std::size_t s = 0; s < spec.seeds.size(); ++s) {
    surfaces.push_back(rough_wear_map_surface(spec, s));
    const auto& f = surfaces.back();
    for (std::size_t l = 0; l < nl; ++l)
      for (std::size_t d = 0; d < nd; ++d) {
        Row r;
        r.seed = static_cast<int>(spec.seeds[s]), r.load = static_cast<int>(l), r.dstar = static_cast<int>(d);
        r.count = std::lround(f.count[l * nd + d]);
        r.volume = f.volume[l * nd + d];
        r.largest = f.largest[l * nd + d];
        for (const auto& p : f.particles)
          if (p.load_index == l && p.dstar_index == d) r.fingerprint += (p.x + 2.0 * p.y) * p.diameter;
        found.push_back(r);
      }
  }
  const RoughWearMap map = combine_surfaces(spec, surfaces);
  const std::vector<int> region = regions(map);

  const std::string gold = WEARSCALE_TEST_DATA "/wear/rough_map_128.csv";
  if (const char* out = std::getenv("WEARSCALE_WRITE_GOLD")) {
    std::FILE* f = std::fopen(out, "w");
    ASSERT_NE(f, nullptr) << out;
    std::fprintf(f, "seed,load_index,dstar_index,count,volume,largest,fingerprint,region\n");
    for (const Row& r : found)
      std::fprintf(f, "%d,%d,%d,%ld,%.17g,%.17g,%.17g,%d\n", r.seed, r.load, r.dstar, r.count, r.volume, r.largest,
                   r.fingerprint, region[static_cast<std::size_t>(r.load) * nd + static_cast<std::size_t>(r.dstar)]);
    std::fclose(f);
    GTEST_SKIP() << "wrote " << out;
  }
  std::ifstream in(gold);
  ASSERT_TRUE(in) << gold;
  std::string line;
  std::vector<Row> want;
  std::vector<int> want_region(nl * nd, -2);
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 's') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream is(line);
    Row r;
    int reg = 0;
    is >> r.seed >> r.load >> r.dstar >> r.count >> r.volume >> r.largest >> r.fingerprint >> reg;
    ASSERT_TRUE(is) << line;
    want.push_back(r);
    want_region[static_cast<std::size_t>(r.load) * nd + static_cast<std::size_t>(r.dstar)] = reg;
  }
  ASSERT_EQ(want.size(), found.size());
  long particles = 0;
  for (std::size_t k = 0; k < want.size(); ++k) {
    const Row &a = found[k], &b = want[k];
    ASSERT_EQ(a.seed, b.seed);
    ASSERT_EQ(a.load, b.load);
    ASSERT_EQ(a.dstar, b.dstar);
    const auto where = testing::Message() << "seed " << a.seed << ", p̃_N = " << spec.loads[a.load]
                                          << ", d*/L = " << spec.critical_diameters[a.dstar];
    EXPECT_EQ(a.count, b.count) << where;
    // The same particles: positions and diameters on the grid, sums in the same order.
    EXPECT_NEAR(a.volume, b.volume, 1e-12 * b.volume) << where;
    EXPECT_EQ(a.largest, b.largest) << where;
    EXPECT_NEAR(a.fingerprint, b.fingerprint, 1e-12 * std::abs(b.fingerprint)) << where;
    particles += b.count;
  }
  for (std::size_t k = 0; k < region.size(); ++k) EXPECT_EQ(region[k], want_region[k]) << "pixel " << k;
  // The gold is not trivial: particles on many pixels, every region present.
  EXPECT_GT(particles, 1000);
  for (int r : {-1, 0, 1, 2}) EXPECT_NE(std::count(want_region.begin(), want_region.end(), r), 0) << "region " << r;
}
