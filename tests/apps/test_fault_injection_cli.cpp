// The disk fails at each write of a small run in turn (an LD_PRELOAD shim,
// tests/support/fail_writes.c: from the N-th write on, every write into the
// output folder fails with ENOSPC, as a file system filling up; likewise
// fsync with EIO and rename with ENOSPC). The same for `contact` and
// `surface generate` (no checkpoint: they are simply run again). For every N:
//  - the program exits with status 2 naming the file, never 3 or a signal;
//  - every file under a final name is complete: byte for byte (run.h5: its
//    datasets) the file of an undisturbed run, and a summary.json only with
//    all the outputs it lists;
//  - the run can be resumed (--resume, the disk working again) to the
//    results of the undisturbed run.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_faults_");
const std::filesystem::path work = work_scratch.path();
// About 30 explicit steps on a 16² grid with a checkpoint every 10: every kind of write of a run
// (checkpoints, run.h5, CSV, XDMF, the plot's script, PNG, summary), in a fraction of a second.
const std::string run_args = "run '" + std::string(WEARSCALE_SOURCE_DIR) +
                             "/cases/pin_on_disc_si_oxide.toml' -j 1 --set scale.macro.grid=16 "
                             "--set scale.macro.distance=0.005 --set run.fft_planning=estimate "
                             "--set run.checkpoint_steps=10 --out out";
// A sphere contact on a 16² grid (HDF5 fields, XDMF, clusters CSV, summary), and a generated surface (HDF5, XDMF).
const std::string contact_args =
    "contact -j 1 --set contact.grid=16 --set contact.size=1e-3 --set contact.sphere.radius=1e-2 --e-star 1e9 "
    "--pressure 1e6 --out out";
const std::string generate_args =
    "surface generate -j 1 --n 32 --size 1e-3 --hurst 0.8 --kl 1 --ks 4 --seed 1 --hprime-rms 0.1 "
    "--set run.fft_planning=estimate --out out --file s.h5";

// The datasets that say an HDF5 output is complete: the same values as the undisturbed run's file.
// (HDF5 files are not byte-identical between runs: object time stamps. A generated surface agrees
// to rounding only: FFTW's measured plans may differ between two processes.)
const std::map<std::string, std::vector<const char*>> h5_datasets = {
    {"run.h5", {"/macro/series/distance", "/macro/series/friction", "/macro/final/pin"}},
    {"contact.h5", {"/surface/height", "/fields/pressure", "/fields/gap"}},
    // Every study's run.h5 holds its headline results; a contact's (the pipeline's series above aside):
    {"contact/run.h5", {"/results/mean_pressure", "/results/contact_fraction"}},
    {"surface/run.h5", {"/results/Sa", "/results/h_rms", "/results/h_prime_rms"}},
    {"s.h5", {"/surface/height"}}};

std::string shim_env(const fs::path& dir, const std::string& op, long at) {
  return "LD_PRELOAD='" + std::string(WEARSCALE_FAULT_SHIM) + "' FAULT_DIR='" + (dir / "out").string() + "' FAULT_OP=" +
         op + " FAULT_AT=" + std::to_string(at) + " FAULT_COUNT_FILE='" + (dir / "count").string() + "'";
}

// The outputs of a run, by file name (hidden files aside).
std::vector<std::string> outputs_in(const fs::path& dir) {
  std::vector<std::string> out;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().filename().string().front() != '.') out.push_back(it->path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

// Every output present under its final name is the complete file of the undisturbed run.
void expect_complete_outputs(const fs::path& got, const fs::path& reference, const std::string& where) {
  const auto files = outputs_in(got);
  const bool has_summary = std::find(files.begin(), files.end(), "summary.json") != files.end();
  for (const auto& f : files) {
    if (f == "checkpoint.h5") continue;  // the state saved so far: checked by resuming
    if (f == "log.txt") continue;        // a sweep run's log: appended as it goes (every attempt), not committed whole
    if (fs::is_directory(got / f)) {     // a sweep's run
      EXPECT_TRUE(fs::is_directory(reference / f)) << where << ": a folder " << f << " the undisturbed run has not";
      if (fs::is_directory(reference / f)) expect_complete_outputs(got / f, reference / f, where + ", " + f);
      continue;
    }
    const bool contact_run = f == "run.h5" && fs::exists(reference / "contact.h5");
    const bool surface_run = f == "run.h5" && fs::exists(reference / "s.h5");
    if (const auto d = h5_datasets.find(contact_run ? "contact/run.h5" : surface_run ? "surface/run.h5" : f);
        d != h5_datasets.end()) {
      wearscale::H5Reader a(reference / f), b(got / f);  // complete: it opens, and holds the same values
      EXPECT_EQ(fs::file_size(reference / f), fs::file_size(got / f)) << where << ": " << f;
      for (const char* s : d->second) {
        const auto x = a.read_series(s), y = b.read_series(s);
        ASSERT_EQ(x.size(), y.size()) << where << ": " << f << s;
        if (f != "s.h5") {
          EXPECT_EQ(x, y) << where << ": " << f << s;
          continue;
        }
        for (std::size_t k = 0; k < x.size(); ++k)
          ASSERT_NEAR(x[k], y[k], 1e-12 * std::abs(x[k]) + 1e-20) << where << ": " << f << s << "[" << k << "]";
      }
      continue;
    }
    EXPECT_TRUE(slurp(got / f) == slurp(reference / f)) << where << ": " << f << " differs from the complete file";
  }
  if (has_summary) {
    EXPECT_EQ(files, outputs_in(reference)) << where << ": a summary.json, but outputs are missing";
  }
}

// Temporary files left behind (".<name>.partial-<pid>"), in `dir` and its subfolders.
std::vector<std::string> partial_files_in(const fs::path& dir) {
  std::vector<std::string> out;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().filename().string().find(".partial") != std::string::npos) out.push_back(it->path().string());
  return out;
}

long count_of(const fs::path& file) {
  long total = 0, n = 0;
  std::ifstream in(file);
  while (in >> n) total += n;  // one line per process that loaded the shim (wearscale, gnuplot, sh)
  return total;
}

// What a command's output folder says it computed: the summary's results (a surface: its heights).
nlohmann::json results_in(const fs::path& dir) {
  if (fs::exists(dir / "sweep.csv")) return slurp(dir / "sweep.csv");
  if (fs::exists(dir / "summary.json")) return nlohmann::json::parse(slurp(dir / "summary.json"))["results"];
  if (!fs::exists(dir / "s.h5")) return "no output";
  nlohmann::json heights = nlohmann::json::array();  // to 10 digits: FFTW's plans may differ in the last bits
  for (double h : wearscale::H5Reader(dir / "s.h5").read_series("/surface/height"))
    heights.push_back(fmt::format("{:.10g}", h));
  return heights;
}

// The command `args` (writing into out/) under the shim failing `op` from its N-th call on, for
// every N it reaches (at most `max_points` of them, evenly spread). `resumable`: it checkpoints,
// so it is continued with --resume; else run again.
void fail_each(const std::string& name, const std::string& args, const std::string& op, long max_points,
               bool resumable) {
  const auto reference = work / ("reference-" + name);
  if (!fs::exists(reference / "out")) {
    ASSERT_EQ(run_cli(args, reference).status, 0);
  }
  const auto probe = work / ("count-" + name + "-" + op);
  fs::remove_all(probe);
  {
    ASSERT_EQ(run_cli(args, probe, shim_env(probe, op, 0)).status, 0) << slurp(probe / "cli.stderr");
  }
  const long points = count_of(probe / "count");
  ASSERT_GT(points, resumable ? 2 : 0) << name << ", " << op << ": the shim saw no call (not loaded?)";
  const long stride = std::max(1L, points / max_points);
  for (long at = 1; at <= points; at += stride) {
    const auto dir = work / (name + "-" + op + "-" + std::to_string(at));
    fs::remove_all(dir);
    const auto r = run_cli(args, dir, shim_env(dir, op, at));
    const std::string where =
        name + ": " + op + " failing from call " + std::to_string(at) + " of " + std::to_string(points);
    ASSERT_NE(r.status, -1) << where << ": killed by a signal";
    EXPECT_EQ(r.status, 2) << where << ": " << r.err;
    EXPECT_THAT(r.err, HasSubstr("out/")) << where << ": the message names the file";
    EXPECT_THAT(r.err, ::testing::Not(HasSubstr("internal error"))) << where;
    expect_complete_outputs(dir / "out", reference / "out", where);
    EXPECT_EQ(partial_files_in(dir / "out"), std::vector<std::string>{}) << where << ": temporary files left behind";
    // The disk works again: the run resumes (from its checkpoint, or afresh) to the undisturbed results.
    // (A run that failed before writing anything leaves no folder: it starts again.)
    std::string again = args;
    if (resumable && fs::exists(dir / "out")) again.replace(again.rfind("--out out"), 9, "--resume out");
    const auto resumed = run_cli(again, dir);
    ASSERT_EQ(resumed.status, 0) << where << ", resumed: " << resumed.err;
    EXPECT_EQ(results_in(dir / "out"), results_in(reference / "out")) << where;
    EXPECT_EQ(outputs_in(dir / "out"), outputs_in(reference / "out")) << where;
    fs::remove_all(dir);
  }
}
}  // namespace

TEST(FaultInjection, TheDiskFillingUpAtEachWriteLeavesNoPartialOutputAndTheRunResumes) {
  fail_each("run", run_args, "write", 40, true);
}

TEST(FaultInjection, AnFsyncFailingAtEachCallLeavesNoPartialOutputAndTheRunResumes) {
  fail_each("run", run_args, "fsync", 12, true);
}

TEST(FaultInjection, ARenameFailingAtEachCallLeavesNoPartialOutputAndTheRunResumes) {
  fail_each("run", run_args, "rename", 12, true);
}

// A sweep of two runs: its run folders, the sweep table, its plots and summary.
TEST(FaultInjection, ASweepOnAFillingDiskLeavesNoPartialOutputAndResumes) {
  const auto dir = work / "sweep-case";
  fs::create_directories(dir);
  std::ofstream(dir / "sweep.toml") << slurp(fs::path(WEARSCALE_SOURCE_DIR) / "cases/pin_on_disc_si_oxide.toml")
                                    << "\n[sweep]\nkey = \"materials.layer.thickness\"\nvalues = [0, 1e-6]\n";
  std::string args = run_args;
  args.replace(args.find("run '"), args.find("' -j") + 1 - args.find("run '"), "run '" + (dir / "sweep.toml").string() + "'");
  fail_each("sweep", args, "write", 6, true);
}

TEST(FaultInjection, AContactStudyOnAFailingDiskLeavesNoPartialOutput) {
  for (const char* op : {"write", "fsync", "rename"}) fail_each("contact", contact_args, op, 12, false);
}

TEST(FaultInjection, AGeneratedSurfaceOnAFailingDiskLeavesNoPartialOutput) {
  for (const char* op : {"write", "fsync", "rename"}) fail_each("generate", generate_args, op, 12, false);
}
