// The steady state of a slide: the means over its second half.
#include <gtest/gtest.h>

#include <vector>

#include "wearscale/dem/sliding_cell.hpp"
#include "wearscale/dem/steady_sliding.hpp"

using namespace wearscale::dem;

TEST(SteadySliding, TakesTheMeansOverTheSecondHalfOfTheSlideOnly) {
  // Running-in (F_T rising) over the first 5 nm, steady F_T = 2, F_N = 4 over the last 5.
  std::vector<SlidingSample> history;
  for (int k = 0; k <= 10; ++k) {
    SlidingSample s;
    s.time = k;
    s.sliding = k * 1e-9;
    s.tangential_force = k < 5 ? 0.2 * k : 2.0;
    s.normal_force = 4.0;
    history.push_back(s);
  }
  const SteadySliding steady = steady_sliding(history);
  EXPECT_EQ(steady.samples, 6u);  // 5 nm to 10 nm
  EXPECT_DOUBLE_EQ(steady.tangential_force, 2.0);
  EXPECT_DOUBLE_EQ(steady.normal_force, 4.0);
  EXPECT_DOUBLE_EQ(steady.friction, 0.5);
}

TEST(SteadySliding, IgnoresTheSampleBeforeSlidingAndGivesNoFrictionWithoutLoad) {
  std::vector<SlidingSample> history(3);
  history[0].tangential_force = 100.0;  // time 0: the state before the slide
  for (int k = 1; k < 3; ++k) {
    history[k].time = k;
    history[k].tangential_force = 1.0;
  }
  const SteadySliding steady = steady_sliding(history);  // no sliding: every sample is in the "second half"
  EXPECT_EQ(steady.samples, 2u);
  EXPECT_DOUBLE_EQ(steady.tangential_force, 1.0);
  EXPECT_EQ(steady.friction, 0.0);
  EXPECT_EQ(steady_sliding(std::vector<SlidingSample>{}).samples, 0u);
}
