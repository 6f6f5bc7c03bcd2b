// The progress reporter: quiet in CI and off a terminal, rate and ETA otherwise.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include <unistd.h>

#include "wearscale/core/log.hpp"
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

// The first rate would include the setup before the first unit of work
// (FFTW plans, a case's checks): it is shown only once there is something to
// measure.
TEST(Progress, ShowsNoRateBeforeAnyWorkIsDone) {
  auto p = Progress::silent(100);
  EXPECT_THAT(p.line(), ::testing::HasSubstr("-- steps/s  ETA --"));
  p.update(10);
  EXPECT_THAT(p.line(), ::testing::HasSubstr("-- steps/s")) << "not within the first half second";
  std::this_thread::sleep_for(std::chrono::milliseconds(510));
  p.update(20);
  EXPECT_THAT(p.line(), ::testing::Not(::testing::HasSubstr("--")));
}

TEST(Progress, ALineIsCutToTheTerminalWidthByCharactersNotBytes) {
  EXPECT_EQ(Progress::fit_to_width("pin-on-disc  42%", 7), "pin-on-");
  EXPECT_EQ(Progress::fit_to_width("short", 80), "short");
  EXPECT_EQ(Progress::fit_to_width("µm → nm", 4), "µm →") << "µ and → are one character each";
  EXPECT_EQ(Progress::fit_to_width("→→→", 0), "");
  EXPECT_GE(Progress::terminal_columns(), 1u);
}

// A message printed while a progress line is drawn starts on a clean line:
// the line is cleared first instead of the message being appended to it.
TEST(Progress, AMessageClearsADrawnProgressLineFirst) {
  std::fflush(stderr);
  const int saved = ::dup(STDERR_FILENO);
  FILE* capture = std::tmpfile();
  ASSERT_NE(capture, nullptr);
  ::dup2(::fileno(capture), STDERR_FILENO);
  log::set_status_line(true);
  log::warn("first");
  log::warn("second");
  std::fflush(stderr);
  ::dup2(saved, STDERR_FILENO);
  ::close(saved);
  std::rewind(capture);
  std::string text;
  for (int c; (c = std::fgetc(capture)) != EOF;) text += static_cast<char>(c);
  std::fclose(capture);
  EXPECT_EQ(text, "\r\033[Kwarning: first\nwarning: second\n") << "cleared once, before the first message only";
}
