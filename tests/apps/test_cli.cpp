// The wearscale program as users meet it: subcommands with --help, exit
// status 0/2, messages that name the problem, and no half-written output.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "wearscale/core/thread_waiting.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_cli_");
const std::filesystem::path work = work_scratch.path();
const std::string hertz_case = std::string(WEARSCALE_SOURCE_DIR) + "/cases/hertz_pin.toml";

const char* kGoodCase = R"(
[case]
name = "cli-test"
[scale.macro]
backend = "hertz"
pin_radius = 3e-3
normal_load = 1.0
elastic_modulus = 73e9
poisson_ratio = 0.17
)";

fs::path write_case(const std::string& name, const std::string& text) {
  fs::create_directories(work);
  const auto p = work / name;
  std::ofstream(p) << text;
  return p;
}

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto pos = s.find(from);
  if (pos == std::string::npos) throw std::logic_error("test case text lacks " + from);
  return s.replace(pos, from.size(), to);
}
}  // namespace

TEST(Cli, BackendsListsTheRegisteredBackends) {
  const auto r = run_cli("backends", work);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("macro/hertz"));
  EXPECT_THAT(r.out, HasSubstr("provides: MacroResult(pin/disc)"));
  const auto j = nlohmann::json::parse(run_cli("backends --json", work).out);
  ASSERT_TRUE(j.is_array());
  EXPECT_EQ(j[0]["kind"], "macro");
}

TEST(Cli, BackendsListTheirKeysFromTheirKeyTables) {
  const auto r = run_cli("backends --keys", work);
  EXPECT_EQ(r.status, 0) << r.err;
  // help_line: "meaning [unit; range; default]: key"
  EXPECT_THAT(r.out, HasSubstr("explicit time step (the adaptive integrator's first step) [s; (0, distance/velocity]; "
                               "default 0.02]: scale.macro.time_step"));
  EXPECT_THAT(r.out, HasSubstr("[[8, 4096]; default 128]: scale.macro.grid"));
  const auto j = nlohmann::json::parse(run_cli("backends --keys --json", work).out);
  bool found = false;
  for (const auto& b : j)
    if (b["kind"] == "macro" && b["name"] == "hertz")
      for (const auto& k : b["keys"])
        if (k["key"] == "scale.macro.profile_points") {
          found = true;
          EXPECT_EQ(k["default"], "201");
          EXPECT_EQ(k["allowed"], "≥ 3");
        }
  EXPECT_TRUE(found);
}

TEST(Cli, EverySubcommandHasHelp) {
  for (const std::string sub : {"run", "backends", "version"}) {
    const auto r = run_cli(sub + " --help", work);
    EXPECT_EQ(r.status, 0) << sub;
    EXPECT_THAT(r.out, HasSubstr("Usage:")) << sub;
  }
  EXPECT_THAT(run_cli("run --help", work).out, HasSubstr("--set"));
  EXPECT_EQ(run_cli("--help", work).status, 0);
}

TEST(Cli, VersionNamesTheLibraries) {
  const auto r = run_cli("version --json", work);
  EXPECT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["libraries"].contains("FFTW"));
  EXPECT_TRUE(j["libraries"].contains("HDF5"));
}

// libgomp reads how its threads wait once, when it loads; the program chooses
// before that (thread_waiting.hpp) unless the user did. OMP_DISPLAY_ENV makes
// libgomp print what it read.
TEST(Cli, ThreadsSpinBrieflyThenSleepUnlessTheUserChose) {
  const std::string clean = "env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT OMP_DISPLAY_ENV=verbose";
  const auto r = run_cli("version", work, "", clean);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr(std::string("GOMP_SPINCOUNT = '") + wearscale::waiting_spin_count + "'"));
  EXPECT_THAT(r.out, HasSubstr(std::string("threads wait: spin ") + wearscale::waiting_spin_count +
                               " times, then sleep (GOMP_SPINCOUNT=" + wearscale::waiting_spin_count +
                               ", set by wearscale)"));
  const auto passive = run_cli("version --json", work, "", clean + " OMP_WAIT_POLICY=passive");
  ASSERT_EQ(passive.status, 0) << passive.err;
  EXPECT_THAT(passive.err, HasSubstr("OMP_WAIT_POLICY = 'PASSIVE'"));
  EXPECT_THAT(passive.err, HasSubstr("GOMP_SPINCOUNT = '0'"));
  EXPECT_EQ(nlohmann::json::parse(passive.out)["threads_wait"], "OMP_WAIT_POLICY=passive (set by the user)");
  const auto spins = run_cli("version", work, "", clean + " GOMP_SPINCOUNT=7");
  EXPECT_THAT(spins.err, HasSubstr("GOMP_SPINCOUNT = '7'"));
  EXPECT_THAT(spins.out, HasSubstr("GOMP_SPINCOUNT=7, set by the user"));
}

TEST(Cli, DashDashVersionPrintsTheVersionAndSucceeds) {
  const auto r = run_cli("--version", work);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.out, ::testing::MatchesRegex("wearscale [0-9]+\\.[0-9]+\\.[0-9]+\n"));
}

TEST(Cli, AnUnknownCommandIsNamedWithTheKnownOnes) {
  for (const std::string line : {"frobnicate", "-j 1 frobnicate --x", "-q frobnicate"}) {
    const auto r = run_cli(line, work);
    EXPECT_EQ(r.status, 2) << line;
    EXPECT_THAT(r.err, HasSubstr("unknown command 'frobnicate'")) << line;
    EXPECT_THAT(r.err, HasSubstr("run, check, backends, version")) << line;
  }
}

TEST(Cli, CommandLineMistakesAreBadInput) {
  EXPECT_EQ(run_cli("", work).status, 2);
  EXPECT_EQ(run_cli("frobnicate", work).status, 2);
  EXPECT_EQ(run_cli("run", work).status, 2);
  EXPECT_EQ(run_cli("run a.toml --bogus", work).status, 2);
}

TEST(Cli, RunWritesResultsAndPrintsJson) {
  const auto out = work / "out-json";
  const auto r = run_cli("run '" + hertz_case + "' --out '" + out.string() + "' --json", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["case"], "hertz-pin");
  EXPECT_NEAR(j["results"]["contact_radius"]["value"].get<double>(), 39.1e-6, 0.05e-6);
  EXPECT_EQ(j["parameters"]["scale"]["macro"]["backend"], "hertz");
  EXPECT_TRUE(fs::exists(out / "run.h5"));
  EXPECT_TRUE(fs::exists(out / "summary.json"));
  EXPECT_TRUE(fs::exists(out / "pressure_profile.csv"));
  for (const auto& e : fs::directory_iterator(out))
    EXPECT_EQ(e.path().filename().string().find(".partial"), std::string::npos) << e.path();
}

TEST(Cli, SetOverridesACaseKey) {
  const auto r = run_cli("run '" + hertz_case + "' --out o2 --json --set scale.macro.normal_load=8", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto a = nlohmann::json::parse(r.out)["results"]["contact_radius"]["value"].get<double>();
  EXPECT_NEAR(a, 2.0 * 39.1e-6, 0.1e-6);  // a ∝ F^(1/3)
}

struct BadInput {
  std::string name, case_text, extra_args, expected;
};

void PrintTo(const BadInput& b, std::ostream* os) { *os << b.name; }

class CliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInput, ExitsWithStatus2NamingTheProblemAndWritesNothing) {
  const auto& p = GetParam();
  const auto out = work / ("bad-" + p.name);
  std::string file = "'" + write_case(p.name + ".toml", p.case_text).string() + "'";
  if (p.case_text.empty()) file = "'" + (work / "does-not-exist.toml").string() + "'";
  const auto r = run_cli("run " + file + " --out '" + out.string() + "' " + p.extra_args, work);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr(p.expected));
  EXPECT_FALSE(fs::exists(out)) << "bad input must not create output";
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CliBadInput,
    ::testing::Values(
        BadInput{"syntax", replace(kGoodCase, "normal_load = 1.0", "normal_load = = 1.0"), "", "TOML syntax error"},
        BadInput{"unknown_key", replace(kGoodCase, "pin_radius", "pin_radiuss"), "", "scale.macro.pin_radiuss"},
        BadInput{"wrong_type", replace(kGoodCase, "normal_load = 1.0", "normal_load = true"), "",
                 "scale.macro.normal_load"},
        BadInput{"out_of_range", replace(kGoodCase, "poisson_ratio = 0.17", "poisson_ratio = 0.6"), "",
                 "[-1, 0.5)"},
        BadInput{"wrong_unit", replace(kGoodCase, "normal_load = 1.0", "normal_load = \"1 mm\""), "",
                 "has unit of m, expected N"},
        BadInput{"missing_file", "", "", "no such case file"},
        BadInput{"unknown_backend", replace(kGoodCase, "\"hertz\"", "\"bem\""), "", "unknown backend"},
        BadInput{"unknown_kind", std::string(kGoodCase) + "[scale.meso]\nbackend = \"x\"\n", "", "unknown scale kind"},
        BadInput{"missing_key", replace(kGoodCase, "pin_radius = 3e-3", ""), "", "scale.macro.pin_radius"},
        BadInput{"bad_set", kGoodCase, "--set scale.macro.normal_load=-1", "scale.macro.normal_load"},
        BadInput{"malformed_set", kGoodCase, "--set nothing", "expected KEY=VALUE"}),
    [](const auto& p) { return p.param.name; });

TEST(Cli, ABadRunLeavesEarlierOutputIntact) {
  const auto out = work / "keep";
  ASSERT_EQ(run_cli("run '" + hertz_case + "' --out '" + out.string() + "'", work).status, 0);
  const auto before = slurp(out / "run.h5");
  const auto r = run_cli("run '" + hertz_case + "' --out '" + out.string() + "' --set scale.macro.pin_radius=0", work);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(slurp(out / "run.h5"), before);
}
