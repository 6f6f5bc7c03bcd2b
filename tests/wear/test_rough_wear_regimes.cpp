// The three wear regimes of §5.3 on small rough surfaces (n = 128, H = 0.8,
// q_l = 8, q_s = n/8, two seeds): with load, no particles (plastic), then
// more and more separated particles, then fewer and larger combined ones,
// while the wear volume keeps rising, more steeply past the maximum number
// of particles (Fig. 5.6–5.7; VERIFICATION.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "wearscale/wear/rough_wear_map.hpp"

using namespace wearscale;
using namespace wearscale::wear;

TEST(RoughWearRegimes, CountRisesThenFallsWhileVolumeKeepsRising) {
  RoughWearMapSpec spec;
  spec.surface.n = 128;
  spec.surface.k_l = 8;
  spec.surface.k_s = 16;
  spec.seeds = {1, 2};
  spec.loads = {0.002, 0.01, 0.03, 0.06, 0.1, 0.14, 0.17, 0.2};
  spec.critical_diameters = {0.08};
  const RoughWearMap map = rough_wear_map(spec);
  std::vector<double> count, volume;
  for (std::size_t l = 0; l < spec.loads.size(); ++l) {
    const auto& p = map.pixel(l, 0);
    std::printf("p~N = %.3f  A/A0 = %.3f  particles %5.1f ± %4.1f  volume/L³ %.3e ± %.1e  largest d/L %.3f%s\n",
                p.load, p.contact_fraction, p.count_mean, p.count_sd, p.volume_mean, p.volume_sd, p.largest_mean,
                p.valid ? "" : "  (invalid)");
    if (p.valid) {
      count.push_back(p.count_mean);
      volume.push_back(p.volume_mean);
    }
  }
  ASSERT_GE(count.size(), 5u);
  // Plastic: no particle at the lightest load.
  EXPECT_EQ(count.front(), 0.0);
  // Separated then combined: the maximum number of particles is reached inside the load range and drops after it
  // (by more than the seed-to-seed scatter: the last valid count is ≥ 10 % below the maximum).
  const auto top = static_cast<std::size_t>(std::max_element(count.begin(), count.end()) - count.begin());
  EXPECT_GT(top, 0u);
  ASSERT_LT(top + 1, count.size());
  EXPECT_LT(count.back(), 0.9 * count[top]);
  // The wear volume rises with the load, and faster past the maximum (dV/dp̃ grows).
  for (std::size_t k = 1; k < volume.size(); ++k) EXPECT_GE(volume[k], volume[k - 1]) << "at load " << k;
  const double before = (volume[top] - volume[top - 1]) / (spec.loads[top] - spec.loads[top - 1]);
  const double after = (volume[top + 1] - volume[top]) / (spec.loads[top + 1] - spec.loads[top]);
  EXPECT_GT(after, before);
}
