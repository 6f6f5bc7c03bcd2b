// `wearscale check CASE` (and --dry-run): a case read as the run reads it,
// every independent error at once, the resolved case with every default and
// the memory printed, nothing run or written; and a mistyped option said in
// one line with the closest option.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

namespace {
const ScratchDir work_scratch("wearscale_check_cli_");
const fs::path work = work_scratch.path();
const fs::path cases = fs::path(WEARSCALE_SOURCE_DIR) / "cases";

// The files and folders under `dir` but the runner's captured output.
std::vector<std::string> written(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename() != "cli.stdout" && e.path().filename() != "cli.stderr") out.push_back(e.path().string());
  return out;
}

std::size_t lines(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }
}  // namespace

TEST(CheckCli, AValidCaseIsPrintedResolvedWithItsDefaultsAndNothingIsWritten) {
  const auto dir = work / "valid";
  auto r = run_cli("check '" + (cases / "pin_on_disc_si_oxide.toml").string() + "' --out run", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("valid; study pipeline (molecular/table → nano/analytic → macro/bem-pin-on-disc)"));
  EXPECT_THAT(r.out, HasSubstr("[scale.macro]"));
  EXPECT_THAT(r.out, HasSubstr("fft_planning = \"measure\"    # default"));  // a default the run applies
  EXPECT_THAT(r.out, HasSubstr("backend = \"bem-pin-on-disc\"\n"));           // a value of the file, unmarked
  EXPECT_THAT(r.out, HasSubstr("memory declared before the run starts"));
  EXPECT_TRUE(written(dir).empty()) << written(dir).front();
  r = run_cli("check '" + (cases / "pin_on_disc_si_oxide.toml").string() + "' --set scale.macro.grid=32 --json", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["valid"].get<bool>());
  EXPECT_EQ(j["parameters"]["scale"]["macro"]["grid"], 32);
  EXPECT_EQ(j["defaults"]["run.fft_planning"], "measure");
  EXPECT_EQ(j["output_dirs"][0], "out/pin-on-disc-si-oxide");
  EXPECT_GT(j["memory"]["runs"][0]["bytes"].get<double>(), 0.0);
  EXPECT_GT(j["memory"]["limit_bytes"].get<double>(), 0.0);
  EXPECT_TRUE(written(dir).empty());
}

// Every shipped case checks valid, through every study (the dem studies read their keys at the start
// of their run: taken up to their check), each in well under a second, and none writes anything.
TEST(CheckCli, EveryShippedCaseChecksValidAndWritesNothing) {
  const auto dir = work / "shipped";
  std::size_t checked = 0;
  for (const auto& e : fs::directory_iterator(cases)) {
    if (e.path().extension() != ".toml") continue;
    const auto r = run_cli("check '" + e.path().string() + "' --json", dir);
    ASSERT_EQ(r.status, 0) << e.path() << "\n" << r.err;
    EXPECT_TRUE(nlohmann::json::parse(r.out)["valid"].get<bool>()) << e.path();
    ++checked;
  }
  EXPECT_GE(checked, 15u);
  EXPECT_TRUE(written(dir).empty()) << written(dir).front();
}

TEST(CheckCli, EveryIndependentErrorOfACaseIsListedAndNothingIsWritten) {
  const auto dir = work / "errors";
  fs::create_directories(dir);
  std::ofstream(dir / "bad.toml") << "[case]\nname = \"bad\"\n[run]\nfft_planning = \"exhaustive\"\n[scale.macro]\n"
                                     "backend = \"hertz\"\npin_radius = \"-3 mm\"\nnormal_load = \"1 N\"\n"
                                     "elastic_modulus = \"73 GPa\"\npoisson_ratio = 0.7\npin_radus = 1\n";
  for (const std::string command : {"check bad.toml", "run bad.toml --out o"}) {
    const auto r = run_cli(command, dir);
    EXPECT_EQ(r.status, 2) << command << "\n" << r.err;
    EXPECT_THAT(r.err, HasSubstr("bad.toml: 4 errors in the case:"));
    EXPECT_THAT(r.err, HasSubstr("1. bad.toml:4: key 'run.fft_planning' = \"exhaustive\": not a known choice"));
    EXPECT_THAT(r.err, HasSubstr("2. bad.toml:7: key 'scale.macro.pin_radius' = \"-3 mm\": out of range; allowed: > 0 m"));
    EXPECT_THAT(r.err, HasSubstr("3. bad.toml:10: key 'scale.macro.poisson_ratio' = 0.7: out of range"));
    EXPECT_THAT(r.err, HasSubstr("4. bad.toml:11: key 'scale.macro.pin_radus' = 1: unknown key"));
    EXPECT_THAT(r.err, HasSubstr("(did you mean 'pin_radius'?)"));
    EXPECT_FALSE(fs::exists(dir / "o"));
    EXPECT_FALSE(fs::exists(dir / "out"));
  }
  // One error alone: its message as it was, no list.
  std::ofstream(dir / "one.toml") << "[case]\nname = \"one\"\n[scale.macro]\nbackend = \"hertz\"\npin_radius = \"3 mm\"\n"
                                     "normal_load = \"1 N\"\nelastic_modulus = \"73 GPa\"\npoisson_ratio = 0.7\n";
  const auto one = run_cli("check one.toml", dir);
  EXPECT_EQ(one.status, 2);
  EXPECT_THAT(one.err, HasSubstr("one.toml:8: key 'scale.macro.poisson_ratio' = 0.7: out of range"));
  EXPECT_THAT(one.err, Not(HasSubstr("errors in the case")));
}

// A study that reads its keys as its run starts (dem/junction): its errors listed alike, before anything is written.
TEST(CheckCli, TheErrorsOfAStudyThatReadsItsKeysInItsRunAreListedToo) {
  const auto dir = work / "dem";
  fs::create_directories(dir);
  std::ofstream(dir / "dj.toml") << "[dem.junction]\ndiameter = \"20 nm\"\nd0 = \"-6 nm\"\nvelocty = 3\n";
  for (const std::string command : {"check dj.toml", "dem junction dj.toml --out o"}) {
    const auto r = run_cli(command, dir);
    EXPECT_EQ(r.status, 2) << command << "\n" << r.err;
    EXPECT_THAT(r.err, HasSubstr("dj.toml: 2 errors in the case:"));
    EXPECT_THAT(r.err, HasSubstr("key 'dem.junction.d0' = \"-6 nm\": out of range; allowed: > 0 m"));
    EXPECT_THAT(r.err, HasSubstr("key 'dem.junction.velocty' = 3: unknown key"));
    EXPECT_FALSE(fs::exists(dir / "o"));
  }
}

TEST(CheckCli, DryRunOfAStudyCommandChecksAsCheckDoes) {
  const auto dir = work / "dry";
  const auto r = run_cli("contact '" + (cases / "rough_contact.toml").string() +
                             "' --set contact.grid=64 --set contact.rough.k_s=16 --pressure 0.05 --out c --dry-run",
                         dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("mean_pressure = 0.05"));
  EXPECT_THAT(r.out, HasSubstr("memory declared before the run starts: 640 KiB (the largest need)"));  // 160 B × 64²
  EXPECT_FALSE(fs::exists(dir / "c"));
  const auto bad = run_cli("contact '" + (cases / "rough_contact.toml").string() +
                               "' --set contact.grid=64 --set contact.rough.k_s=16 --pressure -1 --dry-run",
                           dir);
  EXPECT_EQ(bad.status, 2);
  EXPECT_THAT(bad.err, HasSubstr("--pressure -1"));
}

TEST(CheckCli, AMistypedOptionIsOneLineWithTheClosestOption) {
  const auto dir = work / "typo";
  auto r = run_cli("contact --presure 1e6", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(lines(r.err), 1u) << r.err;  // not CLI11's message and the whole help
  EXPECT_THAT(r.err, HasSubstr("wearscale contact: unknown option '--presure'; did you mean --pressure?"));
  r = run_cli("dem junction --velocty=3", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_THAT(r.err, HasSubstr("wearscale dem junction: unknown option '--velocty'; did you mean --velocity?"));
  r = run_cli("run --zzzzzzzz x.toml", dir);  // nothing close: no suggestion, the help named
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_THAT(r.err, HasSubstr("unknown option '--zzzzzzzz' (the options: wearscale run --help)"));
}
