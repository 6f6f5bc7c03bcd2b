#pragma once
// The curves of Fig. 5.7: one per d*, the mean number of particles against
// p̃_N. The thesis reads each curve's maximum off a smoothed version, "a
// Savitzky-Golay filter of degree 3 on a window of 11 points" (§5.2), so that
// statistical noise does not pick it.
#include <cstddef>
#include <vector>

#include "wearscale/wear/rough_wear_map.hpp"

namespace wearscale::wear {

struct CurveMaximum {
  std::vector<double> smoothed;  ///< the smoothed mean count at every p̃_N of the map
  int window = 11, degree = 3;   ///< the filter used (smaller on a map of fewer than 11 loads)
  bool found = false;            ///< false when no point of the curve is valid
  std::size_t index = 0;         ///< load index of the maximum of the smoothed curve over valid points
  double load = 0.0;             ///< p̃_N there
  double count = 0.0;            ///< the smoothed count there
};

/// The smoothed curve of d* number `i_dstar` and its maximum over the valid
/// pixels. The filter is degree 3 on 11 points, or on a map of n < 11 loads
/// the largest odd window ≤ n with degree ≤ window − 1.
CurveMaximum curve_maximum(const RoughWearMap& map, std::size_t i_dstar);

}  // namespace wearscale::wear
