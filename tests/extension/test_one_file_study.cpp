// One new file adds a study: tests/extension/hertz_study.cpp, compiled into a
// build of the program (and of the keys.md generator) with no other source
// changed, is listed, documented, completed and run like the shipped studies.
// The Python module links the library's registry, so a test study needs its
// own module build to be seen there: not tested here.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir scratch("wearscale-extension-");
}

TEST(OneFileStudy, IsListedWithItsKeysAndSummary) {
  const auto dir = scratch.path() / "list";
  const auto list = run_cli("studies", dir);
  ASSERT_EQ(list.status, 0) << list.err;
  EXPECT_THAT(list.out, HasSubstr("hertz "));
  EXPECT_THAT(list.out, HasSubstr("Hertz contact radius of a sphere on an elastic flat (§8.1)"));
  EXPECT_THAT(list.out, HasSubstr("contact "));  // beside the shipped ones
  const auto keys = run_cli("studies hertz", dir);
  ASSERT_EQ(keys.status, 0) << keys.err;
  EXPECT_THAT(keys.out, HasSubstr("hertz.e_star"));
  EXPECT_THAT(run_cli("studies --help", dir).out, HasSubstr("hertz"));
  const auto misspelt = run_cli("studies hertzz", dir);
  EXPECT_EQ(misspelt.status, 2);
  EXPECT_THAT(misspelt.err, HasSubstr("unknown study 'hertzz'"));
  EXPECT_THAT(misspelt.err, HasSubstr("(did you mean 'hertz'?)"));
}

TEST(OneFileStudy, IsInTheCompletionScripts) {
  const auto dir = scratch.path() / "completion";
  for (const std::string shell : {"bash", "zsh"}) {
    const auto r = run_cli("completion " + shell, dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("hertz")) << shell;
  }
}

TEST(OneFileStudy, IsInTheGeneratedKeysPage) {
  const auto dir = scratch.path() / "keys";
  fs::create_directories(dir);
  const auto page = dir / "keys.md";
  ASSERT_EQ(std::system(("'" + std::string(WEARSCALE_KEYS_DOC) + "' > '" + page.string() + "'").c_str()), 0);
  const std::string text = slurp(page);
  EXPECT_THAT(text, HasSubstr("## `hertz`"));
  EXPECT_THAT(text, HasSubstr("hertz.radius"));
  EXPECT_THAT(text, HasSubstr("## `contact`"));
}

TEST(OneFileStudy, RunsACaseThroughTheRunnerWithTheHertzRadius) {
  const auto dir = scratch.path() / "run";
  fs::create_directories(dir);
  // The unworn pin of §8.1: F = 1 N, R = 3 mm, SiO2 on SiO2 (E* = 37.586 GPa): contact diameter 78.2 µm.
  std::ofstream(dir / "pin.toml") << "[hertz]\nload = \"1 N\"\nradius = \"3 mm\"\ne_star = \"37.586 GPa\"\n";
  const auto r = run_cli("run pin.toml --out out --json", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto summary = nlohmann::json::parse(slurp(dir / "out" / "summary.json"));
  EXPECT_EQ(summary["study"], "hertz");
  const double a = summary["results"]["contact_radius"]["value"].get<double>();
  EXPECT_DOUBLE_EQ(a, std::cbrt(3.0 * 1.0 * 3e-3 / (4.0 * 37.586e9)));
  EXPECT_NEAR(2.0 * a, 78.2e-6, 0.05e-6);
  const auto bad = run_cli("run pin.toml --set hertz.radius=-1 --out bad", dir);
  EXPECT_EQ(bad.status, 2);
  EXPECT_THAT(bad.err, HasSubstr("hertz.radius"));
  EXPECT_FALSE(fs::exists(dir / "bad" / "summary.json"));
}
