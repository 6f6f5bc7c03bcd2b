#pragma once
// The order in which a few workers should start independent tasks of unequal
// cost (the runs of a sweep): the costliest first. Each worker takes the next
// task when it is free (run_on_workers), so the long tasks start early and
// the short ones fill in at the end, instead of a long one starting last and
// running alone (Graham's longest-processing-time rule: within 4/3 of the
// shortest possible wall time).
#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace wearscale {

/// The indices of `costs`, the costliest first; equal costs keep their order.
inline std::vector<std::size_t> costliest_first(const std::vector<double>& costs) {
  std::vector<std::size_t> order(costs.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return costs[a] > costs[b]; });
  return order;
}

}  // namespace wearscale
