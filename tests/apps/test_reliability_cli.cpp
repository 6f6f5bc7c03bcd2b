// Long runs survive interruption and bad input never crashes, as users meet
// it through the program:
//  - a pin-on-disc run killed with SIGKILL mid-way and resumed with --resume
//    ends bit for bit as an uninterrupted run (explicit integrator, one thread);
//  - SIGINT stops a run cleanly: exit 130, checkpoint saved, no unfinished file;
//  - a killed sweep resumes only its unfinished runs;
//  - so does the adaptive one (its checkpoints fall where ARKODE restarts);
//  - each kind of malformed or out-of-range value in cases, surfaces and
//    strength tables: exit 2, a message naming it, and no output written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "reduced_dem_studies.hpp"
#include "cli_runner.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "scratch_dir.hpp"

extern char** environ;

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_reliability_");
const std::filesystem::path work = work_scratch.path();
const std::string pin_on_disc = std::string(WEARSCALE_SOURCE_DIR) + "/cases/pin_on_disc_si_oxide.toml";
// About 2000 explicit steps on a 64² grid: a second or two, long enough to be
// killed mid-way. FFTW's estimate planning makes separate processes compute alike.
const std::string reduced =
    " --set scale.macro.grid=64 --set scale.macro.distance=0.3 --set run.fft_planning=estimate"
    " --set scale.macro.integrator=explicit";

/// Starts the program in the background (the returned pid is the program's own).
pid_t spawn_cli(const std::string& args, const fs::path& cwd) {
  fs::create_directories(cwd);
  std::string cmd = "cd '" + cwd.string() + "' && CI=true exec '" + std::string(WEARSCALE_CLI) + "' " + args +
                    " >cli.stdout 2>cli.stderr";
  std::string sh = "/bin/sh", dash_c = "-c";
  char* argv[] = {sh.data(), dash_c.data(), cmd.data(), nullptr};
  pid_t pid = 0;
  if (::posix_spawn(&pid, "/bin/sh", nullptr, nullptr, argv, environ) != 0) return -1;
  return pid;
}

/// Waits until `ready()` holds while `pid` runs. False if the process ended
/// first (it is then reaped, its status in `status`).
template <class F>
bool wait_until(F ready, pid_t pid, int& status) {
  for (long k = 0; k < 60L * 100 * 10; ++k) {  // gives up after ~10 minutes rather than hang CI
    if (ready()) return true;
    if (::waitpid(pid, &status, WNOHANG) == pid) return false;
    ::usleep(10000);
  }
  return false;
}

/// Starts the program in `cwd` with `args` and sends it `signal` once
/// `ready()` holds; `status` is its wait status. Fails if it could not be
/// started or ended before it was ready (with its stderr).
template <class F>
::testing::AssertionResult stop_when(const std::string& args, const fs::path& cwd, int signal, F ready, int& status) {
  const pid_t pid = spawn_cli(args, cwd);
  if (pid <= 0) return ::testing::AssertionFailure() << "cannot start the program";
  if (!wait_until(ready, pid, status))
    return ::testing::AssertionFailure() << "the run ended before it was ready to be stopped: "
                                         << slurp(cwd / "cli.stderr");
  ::kill(pid, signal);
  ::waitpid(pid, &status, 0);
  return ::testing::AssertionSuccess();
}

/// stop_when with SIGKILL, which must have ended the program.
template <class F>
::testing::AssertionResult killed_when(const std::string& args, const fs::path& cwd, F ready) {
  int status = 0;
  auto stopped = stop_when(args, cwd, SIGKILL, ready, status);
  if (!stopped) return stopped;
  if (!WIFSIGNALED(status)) return ::testing::AssertionFailure() << "the run had finished before it could be killed";
  return ::testing::AssertionSuccess();
}

bool has_partial_file(const fs::path& dir, const std::string& prefix, std::uintmax_t at_least = 0) {
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().filename().string().rfind(prefix, 0) == 0 && fs::file_size(it->path(), ec) >= at_least) return true;
  return false;
}

/// Files of a folder (recursively), hidden ones included.
std::vector<std::string> files_in(const fs::path& dir) {
  std::vector<std::string> out;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file()) out.push_back(fs::relative(it->path(), dir).string());
  std::sort(out.begin(), out.end());
  return out;
}

void expect_same_series(const fs::path& a, const fs::path& b) {
  wearscale::H5Reader ra(a), rb(b);
  for (const char* column : {"distance", "friction", "pin_wear", "disc_wear", "contact_fraction", "layer_share",
                             "bem_iterations"}) {
    const std::string path = std::string("/macro/series/") + column;
    EXPECT_EQ(ra.read_series(path), rb.read_series(path)) << path;  // bit for bit
  }
  EXPECT_EQ(ra.read_series("/macro/final/pin"), rb.read_series("/macro/final/pin"));
}

nlohmann::json results_of(const fs::path& summary) { return nlohmann::json::parse(slurp(summary))["results"]; }

ino_t inode_of(const fs::path& p) {
  struct stat st {};
  ::stat(p.c_str(), &st);
  return st.st_ino;
}

void write_file(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}
}  // namespace

TEST(Resume, AKilledRunResumesToTheResultsOfAnUninterruptedRunBitForBit) {
  const auto dir = work / "kill";
  const std::string fields = " --set scale.macro.fields_every=500";  // snapshots before and after the kill
  ASSERT_EQ(run_cli("run '" + pin_on_disc + "'" + reduced + fields + " --out reference", dir).status, 0);

  const std::string args = "run '" + pin_on_disc + "'" + reduced + fields + " --set run.checkpoint_steps=25";
  ASSERT_TRUE(killed_when(args + " --out part", dir, [&] { return fs::exists(dir / "part" / "checkpoint.h5"); }));
  // A killed run leaves complete files or none: only the checkpoint (and maybe a temporary file, and the
  // small lock file that the next run takes over).
  for (const auto& f : files_in(dir / "part"))
    EXPECT_TRUE(f == "checkpoint.h5" || f == ".wearscale.lock" || f.find(".partial-") != std::string::npos) << f;

  // Resuming with other parameters is refused, naming the key.
  auto r = run_cli(args + " --set scale.macro.grid=32 --resume part", dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("key 'scale.macro.grid' was 64, is now 32"));

  r = run_cli(args + " --resume part", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("resuming macro/bem-pin-on-disc at s = "));
  expect_same_series(dir / "reference" / "run.h5", dir / "part" / "run.h5");
  {
    wearscale::H5Reader a(dir / "reference" / "run.h5"), b(dir / "part" / "run.h5");
    for (const char* snapshot : {"/macro/fields/000000/pressure", "/macro/fields/000001/pin"}) {
      ASSERT_TRUE(b.exists(snapshot)) << snapshot;
      EXPECT_EQ(a.read_series(snapshot), b.read_series(snapshot)) << snapshot;
    }
  }
  EXPECT_EQ(results_of(dir / "part" / "summary.json"), results_of(dir / "reference" / "summary.json"));
  EXPECT_EQ(slurp(dir / "part" / "friction.csv"), slurp(dir / "reference" / "friction.csv"));
  EXPECT_FALSE(fs::exists(dir / "part" / "checkpoint.h5")) << "a completed run keeps no checkpoint";
  EXPECT_FALSE(has_partial_file(dir / "part", ".")) << "temporary files of the killed run are cleaned up";

  // Resuming a completed run changes nothing.
  const auto inode = inode_of(dir / "part" / "run.h5");
  r = run_cli(args + " --resume part", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("already complete"));
  EXPECT_THAT(r.err, HasSubstr("kept part/run.h5"));
  EXPECT_THAT(r.err, ::testing::Not(HasSubstr("wrote"))) << "it wrote nothing, and says so";
  EXPECT_EQ(inode_of(dir / "part" / "run.h5"), inode);
  fs::remove_all(dir);
}

// A nano/dem junction run (one DEM junction, one thread) killed after a
// checkpoint resumes from the saved DEM state to the same fit, bit for bit.
TEST(Resume, AKilledDemJunctionRunResumesFromItsDemStateBitForBit) {
  const auto dir = work / "dem";
  const std::string junction = std::string(WEARSCALE_SOURCE_DIR) + "/cases/junction_sio2.toml";
  const std::string args = "run '" + junction +
                           "' -j 1 --set scale.nano.length=12 --set scale.nano.height=6 --set scale.nano.velocity=50"
                           " --set scale.nano.contact_ratios=[1.0] --set scale.nano.pressures=[1e9]"
                           " --set scale.nano.cache=false --set run.checkpoint_steps=100";
  ASSERT_EQ(run_cli(args + " --out reference", dir).status, 0);

  ASSERT_TRUE(killed_when(args + " --out part", dir, [&] { return fs::exists(dir / "part" / "checkpoint.h5"); }));

  const auto r = run_cli(args + " --resume part", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("resumes at step"));
  EXPECT_EQ(results_of(dir / "part" / "summary.json"), results_of(dir / "reference" / "summary.json"));
  EXPECT_FALSE(fs::exists(dir / "part" / "checkpoint.h5")) << "a completed run keeps no checkpoint";
  fs::remove_all(dir);
}

TEST(Resume, SigintStopsCleanlyWithStatus130AndTheRunResumes) {
  const auto dir = work / "sigint";
  ASSERT_EQ(run_cli("run '" + pin_on_disc + "'" + reduced + " --out reference", dir).status, 0);
  const std::string args = "run '" + pin_on_disc + "'" + reduced;  // default policy: saves on SIGINT
  int status = 0;
  // run.h5 is being written: the signal handlers are in place.
  ASSERT_TRUE(stop_when(args + " --out stopped", dir, SIGINT,
                        [&] { return has_partial_file(dir / "stopped", ".run.h5.partial-"); }, status));
  ASSERT_TRUE(WIFEXITED(status)) << "SIGINT must not kill the process outright";
  EXPECT_EQ(WEXITSTATUS(status), 130) << slurp(dir / "cli.stderr");
  const std::string err = slurp(dir / "cli.stderr");
  EXPECT_THAT(err, HasSubstr("interrupted by SIGINT"));
  EXPECT_THAT(err, HasSubstr(" -j 1 --resume stopped")) << "the hint repeats the threads (ctest runs on one)";
  EXPECT_EQ(files_in(dir / "stopped"), std::vector<std::string>{"checkpoint.h5"}) << "unfinished files are removed";

  const auto r = run_cli(args + " --resume stopped", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  expect_same_series(dir / "reference" / "run.h5", dir / "stopped" / "run.h5");
  fs::remove_all(dir);
}

using DemStudy = wearscale::test_support::ReducedDemStudy;
const auto& dem_studies = wearscale::test_support::reduced_dem_studies;

// The output of two runs of a DEM study is the same: results, history and
// snapshots bit for bit, and no checkpoint or temporary file is left.
void expect_same_dem_outputs(const DemStudy& study, const fs::path& a, const fs::path& b) {
  EXPECT_EQ(results_of(a / "summary.json"), results_of(b / "summary.json"));
  if (!study.dump.empty()) {
    EXPECT_EQ(slurp(a / (study.name + "_history.csv")), slurp(b / (study.name + "_history.csv")));
    const std::string dump = slurp(b / study.dump);
    EXPECT_GT(dump.size(), 0u);
    EXPECT_TRUE(slurp(a / study.dump) == dump) << "the snapshots differ";
  }
  EXPECT_FALSE(fs::exists(b / "checkpoint.h5")) << "a completed run keeps no checkpoint";
  EXPECT_FALSE(has_partial_file(b, ".")) << "no temporary file is left";
}

class DemStudyResume : public ::testing::TestWithParam<DemStudy> {};

// Killed with SIGKILL after its first checkpoint, the study resumes with
// --resume to the outputs of an uninterrupted run (one thread).
TEST_P(DemStudyResume, AKilledStudyResumesToTheOutputsOfAnUninterruptedRunBitForBit) {
  const DemStudy& study = GetParam();
  const auto dir = work / ("dem-kill-" + study.label);
  const std::string args = "-j 1 " + study.args + " --set run.checkpoint_steps=200";
  ASSERT_EQ(run_cli(args + " --out reference", dir).status, 0);

  ASSERT_TRUE(killed_when(args + " --out part", dir, [&] { return fs::exists(dir / "part" / "checkpoint.h5"); }));

  const auto r = run_cli(args + " --resume part", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("resumes at step"));
  expect_same_dem_outputs(study, dir / "reference", dir / "part");
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(EveryStudy, DemStudyResume, ::testing::ValuesIn(dem_studies),
                         [](const ::testing::TestParamInfo<DemStudy>& p) { return p.param.label; });

#ifdef WEARSCALE_DEM_LAMMPS
// The same on the LAMMPS engine ([dem] engine = "lammps"): its state is a
// LAMMPS restart file and its clocks, in the same checkpoint; the cells
// shrink-wrapped along z (rough shear, trapped particles, oxide asperity)
// keep the margins of the box they were created with.
std::vector<DemStudy> on_lammps(const std::vector<DemStudy>& studies) {
  std::vector<DemStudy> out;
  for (auto s : studies) {
    s.args += " --set dem.engine=lammps";
    s.label += "_lammps";  // a folder of its own beside the wearscale run's
    out.push_back(s);
  }
  return out;
}
INSTANTIATE_TEST_SUITE_P(EveryStudyOnLammps, DemStudyResume, ::testing::ValuesIn(on_lammps(dem_studies)),
                         [](const ::testing::TestParamInfo<DemStudy>& p) { return p.param.label; });
#endif

// A DEM study stops on SIGINT within a chunk of steps, with status 130, its
// state saved and its snapshots kept for the resumed run, which then ends as
// an uninterrupted one. Resuming it again reports it complete; resuming it
// with other parameters is refused, naming the key.
TEST(Resume, SigintStopsADemStudyCleanlyAndItResumes) {
  const auto dir = work / "dem-sigint";
  const DemStudy& study = dem_studies.front();
  const std::string args = "-j 1 " + study.args + " --set dem.junction.sliding_distance='12 nm'";
  ASSERT_EQ(run_cli(args + " --out reference", dir).status, 0);
  int status = 0;
  // The first snapshot is written: the junction slides.
  ASSERT_TRUE(stop_when(args + " --out stopped", dir, SIGINT,
                        [&] { return has_partial_file(dir / "stopped", ".junction.dump.partial-", 1); }, status));
  ASSERT_TRUE(WIFEXITED(status)) << "SIGINT must not kill the process outright";
  EXPECT_EQ(WEXITSTATUS(status), 130) << slurp(dir / "cli.stderr");
  const std::string err = slurp(dir / "cli.stderr");
  EXPECT_THAT(err, HasSubstr("interrupted by SIGINT"));
  EXPECT_THAT(err, HasSubstr("--resume stopped"));
  const auto left = files_in(dir / "stopped");
  ASSERT_EQ(left.size(), 2u) << "the checkpoint and the snapshots so far, nothing else";
  EXPECT_EQ(left[1], "checkpoint.h5");
  EXPECT_THAT(left[0], testing::StartsWith(".junction.dump.partial-"));

  // Stopped again once resumed: the hint is the resumed command, --resume once.
  ASSERT_TRUE(stop_when(args + " --resume stopped", dir, SIGINT,
                        [&] { return has_partial_file(dir / "stopped", ".run.h5.partial-"); }, status));
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130) << slurp(dir / "cli.stderr");
  const std::string again = slurp(dir / "cli.stderr");
  const auto hint = again.find("continue with:");
  ASSERT_NE(hint, std::string::npos) << again;
  const std::string line = again.substr(hint, again.find('\n', hint) - hint);
  EXPECT_THAT(line, HasSubstr("--resume stopped"));
  EXPECT_EQ(line.find("--resume"), line.rfind("--resume")) << line;

  auto r = run_cli(args + " --resume stopped", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  expect_same_dem_outputs(study, dir / "reference", dir / "stopped");

  r = run_cli(args + " --resume stopped --json", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("already complete"));
  EXPECT_EQ(nlohmann::json::parse(r.out)["results"], results_of(dir / "reference" / "summary.json"));
  r = run_cli(args + " --set dem.junction.pressure=2e8 --resume stopped", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("dem.junction.pressure"));
  fs::remove_all(dir);
}

TEST(Resume, AKilledSweepRerunsOnlyItsUnfinishedRuns) {
  const auto dir = work / "sweep";
  std::string sweep_case = slurp(pin_on_disc);
  sweep_case += "\n[sweep]\nkey = \"materials.layer.thickness\"\nvalues = [0, 1e-6, 2e-6]\nparallel = false\n";
  write_file(dir / "sweep.toml", sweep_case);
  const std::string args = "run sweep.toml --set scale.macro.grid=32 --set scale.macro.distance=0.2 "
                           "--set run.fft_planning=estimate --set run.checkpoint_steps=25";
  ASSERT_EQ(run_cli(args + " --out reference", dir).status, 0);

  const auto second = dir / "part" / "thickness=1e-06";
  ASSERT_TRUE(killed_when(args + " --out part", dir, [&] { return fs::exists(second / "checkpoint.h5"); }));
  const auto first = dir / "part" / "thickness=0" / "run.h5";
  ASSERT_TRUE(fs::exists(first)) << "the sweep runs its values in order, one at a time";
  const auto inode = inode_of(first);
  EXPECT_FALSE(fs::exists(second / "run.h5"));

  const auto r = run_cli(args + " --resume part --json", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("1 of 3 runs complete"));
  EXPECT_EQ(inode_of(first), inode) << "a finished run is not run again";
  const auto reference = nlohmann::json::parse(slurp(dir / "reference" / "summary.json"))["sweep"]["runs"];
  const auto resumed = nlohmann::json::parse(r.out)["sweep"]["runs"];
  ASSERT_EQ(resumed.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(resumed[k]["results"], reference[k]["results"]) << k;
  EXPECT_EQ(slurp(dir / "part" / "sweep.csv"), slurp(dir / "reference" / "sweep.csv"));
  for (const auto& f : files_in(dir / "part")) EXPECT_EQ(f.find("checkpoint.h5"), std::string::npos) << f;
  fs::remove_all(dir);
}

TEST(Resume, AKilledAdaptiveRunResumesBitForBitToo) {
  const auto dir = work / "adaptive";
  const std::string args = "run '" + pin_on_disc + "' --set scale.macro.grid=64 --set scale.macro.distance=0.3 "
                           "--set scale.macro.integrator=adaptive --set run.fft_planning=estimate "
                           "--set run.checkpoint_steps=1";  // at every restart of the integrator
  ASSERT_EQ(run_cli(args + " --out reference", dir).status, 0);
  ASSERT_TRUE(killed_when(args + " --out part", dir, [&] { return fs::exists(dir / "part" / "checkpoint.h5"); }));
  const auto r = run_cli(args + " --resume part", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  expect_same_series(dir / "reference" / "run.h5", dir / "part" / "run.h5");
  EXPECT_EQ(results_of(dir / "part" / "summary.json"), results_of(dir / "reference" / "summary.json"));
  fs::remove_all(dir);
}

TEST(Resume, MistakesAreBadInput) {
  const auto dir = work / "resume-mistakes";
  auto r = run_cli("run '" + pin_on_disc + "' --resume nowhere", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("--resume nowhere: no such folder"));
  fs::create_directories(dir / "a");
  r = run_cli("run '" + pin_on_disc + "' --resume a --out b", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("name different folders"));
  EXPECT_FALSE(fs::exists(dir / "b"));
  write_file(dir / "c" / "checkpoint.h5", "not HDF5");
  r = run_cli("run '" + pin_on_disc + "' --resume c", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("checkpoint.h5: not an HDF5 file"));
  EXPECT_EQ(files_in(dir / "c"), std::vector<std::string>{"checkpoint.h5"});
  // The same for a DEM study.
  const std::string junction = dem_studies.front().args;
  r = run_cli(junction + " --resume nowhere", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("--resume nowhere: no such folder"));
  r = run_cli(junction + " --resume a --out b", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("name different folders"));
  EXPECT_FALSE(fs::exists(dir / "b"));
  r = run_cli(junction + " --resume c", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("checkpoint.h5: not an HDF5 file"));
  EXPECT_EQ(files_in(dir / "c"), std::vector<std::string>{"checkpoint.h5"});
  r = run_cli(junction + " --set run.checkpoint_steps=-5 --out d", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("run.checkpoint_steps"));
  EXPECT_FALSE(fs::exists(dir / "d"));
  fs::remove_all(dir);
}

// ---------------------------------------------------------------------------
// Bad inputs: one row per kind of malformed or out-of-range value.

struct BadFile {
  std::string name;
  std::string args;                                    ///< after the program name; OUT is the output folder
  std::vector<std::pair<std::string, std::string>> files;  ///< written into the work folder first
  std::string expected;                                ///< in the message
};
void PrintTo(const BadFile& b, std::ostream* os) { *os << b.name; }

class BadInputTable : public ::testing::TestWithParam<BadFile> {};

TEST_P(BadInputTable, ExitsWithStatus2NamingTheProblemAndWritesNothing) {
  const auto& p = GetParam();
  const auto dir = work / ("bad-" + p.name);
  for (const auto& [name, text] : p.files) write_file(dir / name, text);
  std::string args = p.args;
  args.replace(args.find("OUT"), 3, "out");
  const auto r = run_cli(args, dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr(p.expected));
  EXPECT_THAT(r.err, ::testing::Not(HasSubstr("internal error")));
  EXPECT_FALSE(fs::exists(dir / "out")) << "bad input must write nothing";
  fs::remove_all(dir);
}

namespace {
const std::string run_pod = "run '" + pin_on_disc + "' --set scale.macro.grid=32 --set scale.macro.distance=0.001 --out OUT ";
const std::string contact = "contact --surface h.txt --e-star 1e9 --pressure 1e6 --out OUT ";
const std::string with_table = run_pod + "--set scale.molecular.tables.Si=si.csv";
const std::string good_table_head = "# material: Si\npressure_GPa,sigma_max_GPa,sigma_dyn_GPa\n";
}  // namespace

INSTANTIATE_TEST_SUITE_P(
    Cases, BadInputTable,
    ::testing::Values(
        // Case files and --set values.
        BadFile{"case_not_toml", "run case.toml --out OUT", {{"case.toml", "[case\nname = 1\n"}}, "TOML syntax error"},
        BadFile{"case_binary", "run case.toml --out OUT", {{"case.toml", std::string("\xff\xfe\x00\x01[a]", 7)}},
                 "case.toml"},
        BadFile{"case_is_a_folder", "run sub --out OUT", {{"sub/x", ""}}, "is a directory"},
        BadFile{"grid_out_of_range", run_pod + "--set scale.macro.grid=4", {}, "scale.macro.grid"},
        BadFile{"grid_not_integer", run_pod + "--set scale.macro.grid=64.5", {}, "expected an integer"},
        BadFile{"velocity_nan", run_pod + "--set scale.macro.velocity=nan", {}, "scale.macro.velocity"},
        BadFile{"size_infinite", run_pod + "--set scale.macro.size=inf", {}, "scale.macro.size"},
        BadFile{"velocity_not_a_quantity", run_pod + "--set scale.macro.velocity='\"fast\"'", {},
                 "cannot read a quantity"},
        BadFile{"load_wrong_unit", run_pod + "--set scale.macro.normal_load='\"1 m\"'", {}, "has unit of m, expected"},
        BadFile{"checkpoint_interval_negative", run_pod + "--set run.checkpoint_interval=-1", {},
                 "run.checkpoint_interval"},
        BadFile{"checkpoint_interval_wrong_unit", run_pod + "--set run.checkpoint_interval='\"5 m\"'", {},
                 "has unit of m, expected s"},
        BadFile{"checkpoint_steps_fraction", run_pod + "--set run.checkpoint_steps=2.5", {}, "run.checkpoint_steps"},
        BadFile{"fft_planning_unknown", run_pod + "--set run.fft_planning=patient", {}, "\"measure\", \"estimate\""},
        BadFile{"run_key_misspelt", run_pod + "--set run.checkpoint_intervall=60", {}, "did you mean 'checkpoint_interval'"},
        BadFile{"sweep_values_empty", run_pod + "--set sweep.key=materials.layer.thickness --set 'sweep.values=[]'",
                 {}, "sweep.values"},
        // Surfaces (topography files).
        BadFile{"surface_ragged", contact, {{"h.txt", "# lx = 1 mm\n1 2 3\n4 5\n"}}, "h.txt: line 3"},
        BadFile{"surface_nan", contact, {{"h.txt", "# lx = 1 mm\n1 2\nnan 4\n"}}, "1 of 4 points (25 %) have no measured height"},
        BadFile{"surface_overflow", contact, {{"h.txt", "# lx = 1 mm\n1 2\n1e999 4\n"}}, "not a finite number"},
        BadFile{"surface_text", contact, {{"h.txt", "# lx = 1 mm\n1 2\n3 x\n"}}, "'x' is not a number"},
        BadFile{"surface_empty_value", contact, {{"h.txt", "# lx = 1 mm\n1,2\n3,,4\n"}}, "an empty value"},
        BadFile{"surface_empty", contact, {{"h.txt", "# only a comment\n"}}, "no height data"},
        BadFile{"surface_without_size", contact, {{"h.txt", "1 2\n3 4\n"}}, "size of the topography is not given"},
        BadFile{"surface_negative_size", contact, {{"h.txt", "# lx = -1 mm\n1 2\n3 4\n"}}, "is not a length"},
        BadFile{"surface_missing", contact, {}, "h.txt: no such topography file"},
        BadFile{"surface_not_hdf5", "contact --surface h.h5 --e-star 1e9 --pressure 1e6 --out OUT",
                 {{"h.h5", "1 2\n3 4\n"}}, "not an HDF5 file"},
        // Strength tables.
        BadFile{"table_missing_column", with_table, {{"si.csv", "pressure_GPa,sigma_max_GPa\n0,1\n1,2\n"}},
                 "missing column 'sigma_dyn_Pa'"},
        BadFile{"table_not_a_number", with_table, {{"si.csv", good_table_head + "0,10,1\n5,ten,1\n"}},
                 "column sigma_max_GPa = 'ten' is not a number"},
        BadFile{"table_nan", with_table, {{"si.csv", good_table_head + "0,10,1\n5,nan,1\n"}}, "NaN or infinite"},
        BadFile{"table_negative_strength", with_table, {{"si.csv", good_table_head + "0,10,1\n5,-1,1\n"}},
                 "negative strength"},
        BadFile{"table_pressure_decreasing", with_table, {{"si.csv", good_table_head + "0,10,1\n5,9,1\n3,8,1\n"}},
                 "pressures must not decrease"},
        BadFile{"table_ragged", with_table, {{"si.csv", good_table_head + "0,10,1\n5,9\n"}}, "the header has 3 columns"},
        BadFile{"table_one_row", with_table, {{"si.csv", good_table_head + "0,10,1\n"}}, "at least two pressures"},
        BadFile{"table_empty", with_table, {{"si.csv", ""}}, "empty strength table"},
        BadFile{"table_named_in_case", with_table, {{"si.csv", "garbage\n"}}, "scale.molecular.tables.Si"}),
    [](const auto& p) { return p.param.name; });

TEST(Stop, SigtermEndsALongFrictionalContactSolveWithinAnIterationAndWritesNothing) {
  // A contact solve of minutes hears SIGTERM at its next iteration (it used to
  // finish the solve first): status 130, the iteration named, no folder left.
  const auto dir = work / "sigterm_contact";
  fs::create_directories(dir);
  const std::string args = "contact '" WEARSCALE_SOURCE_DIR "/cases/frictional_contact.toml' --set contact.grid=512 --set contact.rough.k_s=128 "
                           "-v --out stopped";
  int status = 0;
  ASSERT_TRUE(stop_when(args, dir, SIGTERM,
                        [&] { return slurp(dir / "cli.stderr").find("iteration 10,") != std::string::npos; }, status));
  ASSERT_TRUE(WIFEXITED(status)) << "SIGTERM must not kill the process outright";
  EXPECT_EQ(WEXITSTATUS(status), 130) << slurp(dir / "cli.stderr");
  const std::string err = slurp(dir / "cli.stderr");
  EXPECT_THAT(err, HasSubstr("frictional-contact (Algorithm 1): stopped at iteration"));
  EXPECT_THAT(err, HasSubstr("nothing was written")) << "no --resume hint for a folder that does not exist";
  EXPECT_FALSE(fs::exists(dir / "stopped"));
  fs::remove_all(dir);
}
