// The three wear regimes of §5.3 at the thesis' size (VERIFICATION.md): n = 512,
// H = 0.8, q_l = 8, q_s = n/8, five surfaces, d*/L = 0.07 (the curve of
// Fig. 5.8): no particles at light loads (plastic), then the number of
// particles rises and falls (separated → combined) while the wear volume
// keeps rising, steeply past the maximum. The fast version (n = 128) is
// tests/wear/test_rough_wear_regimes.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "wearscale/wear/rough_wear_map.hpp"

using namespace wearscale;
using namespace wearscale::wear;

TEST(RoughWearRegimes512, ThreeRegimesOnFiveSurfaces) {
  RoughWearMapSpec spec;  // n = 512, H = 0.8, q_l = 8, q_s = 64, seeds 1…5
  spec.loads = {0.005, 0.02, 0.04, 0.06, 0.08, 0.1, 0.13, 0.16, 0.2, 0.25};
  spec.critical_diameters = {0.07};
  const RoughWearMap map = rough_wear_map(spec);
  std::vector<double> count, volume, load;
  for (std::size_t l = 0; l < spec.loads.size(); ++l) {
    const auto& p = map.pixel(l, 0);
    std::printf("p~N = %.3f  A/A0 = %.3f  particles %6.1f ± %5.1f  volume/L³ %.3e ± %.1e  largest d/L %.3f%s\n",
                p.load, p.contact_fraction, p.count_mean, p.count_sd, p.volume_mean, p.volume_sd, p.largest_mean,
                p.valid ? "" : "  (invalid)");
    if (!p.valid) break;  // the curves of Fig. 5.7 are cut where the map is crossed
    count.push_back(p.count_mean);
    volume.push_back(p.volume_mean);
    load.push_back(p.load);
  }
  ASSERT_GE(count.size(), 5u);
  EXPECT_EQ(count.front(), 0.0);  // plastic
  const auto top = static_cast<std::size_t>(std::max_element(count.begin(), count.end()) - count.begin());
  EXPECT_GT(top, 0u);
  ASSERT_LT(top + 1, count.size());
  EXPECT_LT(count.back(), 0.9 * count[top]);  // separated → combined
  for (std::size_t k = 1; k < volume.size(); ++k) EXPECT_GE(volume[k], volume[k - 1]) << "at load " << load[k];
  const double before = (volume[top] - volume[top - 1]) / (load[top] - load[top - 1]);
  const double after = (volume[top + 1] - volume[top]) / (load[top + 1] - load[top]);
  EXPECT_GT(after, before);  // severe wear past the maximum
}
