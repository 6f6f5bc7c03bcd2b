#include "wearscale/wear/wear_curves.hpp"

#include <algorithm>

#include "wearscale/core/savitzky_golay.hpp"

namespace wearscale::wear {

CurveMaximum curve_maximum(const RoughWearMap& map, std::size_t i_dstar) {
  const std::size_t n = map.spec.loads.size();
  CurveMaximum out;
  std::vector<double> load(n), count(n);
  for (std::size_t l = 0; l < n; ++l) {
    load[l] = map.pixel(l, i_dstar).load;
    count[l] = map.pixel(l, i_dstar).count_mean;
  }
  out.window = static_cast<int>(std::min<std::size_t>(11, n % 2 == 1 ? n : n - 1));
  out.degree = std::min(3, out.window - 1);
  out.smoothed = savitzky_golay(load, count, out.window, out.degree);
  for (std::size_t l = 0; l < n; ++l) {
    if (!map.pixel(l, i_dstar).valid) continue;
    if (!out.found || out.smoothed[l] > out.count) {
      out.found = true;
      out.index = l;
      out.load = load[l];
      out.count = out.smoothed[l];
    }
  }
  return out;
}

}  // namespace wearscale::wear
