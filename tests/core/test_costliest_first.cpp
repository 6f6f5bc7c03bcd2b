// The order in which a sweep starts its runs on a few workers.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "wearscale/core/costliest_first.hpp"

using namespace wearscale;

namespace {
// Wall time of tasks taken in `order` by `workers` workers, each taking the next when free.
double makespan(const std::vector<double>& cost, const std::vector<std::size_t>& order, std::size_t workers) {
  std::vector<double> free_at(workers, 0.0);
  for (std::size_t k : order) *std::min_element(free_at.begin(), free_at.end()) += cost[k];
  return *std::max_element(free_at.begin(), free_at.end());
}
}  // namespace

TEST(CostliestFirst, StartsTheCostliestTaskFirstAndKeepsTheOrderOfEqualOnes) {
  EXPECT_EQ(costliest_first({1.0, 3.0, 2.0, 3.0, 0.0}), (std::vector<std::size_t>{1, 3, 2, 0, 4}));
  EXPECT_EQ(costliest_first({}), std::vector<std::size_t>{});
  EXPECT_EQ(costliest_first({0.0, 0.0, 0.0}), (std::vector<std::size_t>{0, 1, 2}));  // nothing known: as given
}

TEST(CostliestFirst, TwoWorkersFinishTogetherWhereTheGivenOrderLeavesOneAlone) {
  // The main job's measured runs as given (bare Si ... bulk SiO2, the bulk
  // run the longest, last): in that order one worker runs it alone at the end.
  const std::vector<double> cost{113, 334, 399, 484, 518, 593};
  std::vector<std::size_t> given{0, 1, 2, 3, 4, 5};
  const double total = 113 + 334 + 399 + 484 + 518 + 593;
  EXPECT_GT(makespan(cost, given, 2), 0.57 * total);
  EXPECT_LT(makespan(cost, costliest_first(cost), 2), 0.55 * total);
}
