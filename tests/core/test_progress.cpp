// The progress reporter: quiet in CI and off a terminal, rate and ETA otherwise.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <thread>

#include <unistd.h>

#include "wearscale/core/progress.hpp"

using namespace wearscale;

TEST(Progress, IsSilentWhenCIIsSet) {
  ::setenv("CI", "true", 1);
  EXPECT_FALSE(Progress::terminal_is_interactive());
  Progress p("run", 10);
  EXPECT_FALSE(p.enabled());
  ::unsetenv("CI");
}

TEST(Progress, IsSilentWhenStderrIsNotATerminal) {
  // ctest pipes stderr, so a reporter made here never draws.
  ::unsetenv("CI");
  EXPECT_EQ(Progress::terminal_is_interactive(), ::isatty(2) != 0);
}

TEST(Progress, ReportsRateAndEta) {
  auto p = Progress::silent(100);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  p.update(50);
  EXPECT_GT(p.rate(), 0.0);
  EXPECT_GT(p.eta_seconds(), 0.0);
  EXPECT_LT(p.eta_seconds(), 10.0);
  EXPECT_THAT(p.line(), ::testing::HasSubstr("50%"));
  EXPECT_THAT(p.line(), ::testing::HasSubstr("ETA"));
}

// A resumed run starts its reporter at the work done before the stop: shown
// as done, but not counted in the rate (which would overstate it).
TEST(Progress, AResumedRunCountsOnlyItsOwnWorkInTheRate) {
  auto p = Progress::silent(100);
  p.start_at(60);
  EXPECT_THAT(p.line(), ::testing::HasSubstr("60%"));
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  p.update(60);
  EXPECT_EQ(p.rate(), 0.0);  // nothing done since the start
  p.update(70);
  EXPECT_GT(p.rate(), 0.0);
  EXPECT_LT(p.rate(), 10.0 / 0.02);  // 10 steps in at least 20 ms, not 70
}
