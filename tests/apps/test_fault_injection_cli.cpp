// The disk fails at each write of a small run in turn (an LD_PRELOAD shim,
// tests/support/fail_writes.c: from the N-th write on, every write into the
// output folder fails with ENOSPC, as a file system filling up; likewise
// fsync with EIO and rename with ENOSPC). For every N:
//  - the program exits with status 2 naming the file, never 3 or a signal;
//  - every file under a final name is complete: byte for byte (run.h5: its
//    datasets) the file of an undisturbed run, and a summary.json only with
//    all the outputs it lists;
//  - the run can be resumed (--resume, the disk working again) to the
//    results of the undisturbed run.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "wearscale/core/hdf5_file.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const fs::path work = fs::temp_directory_path() / ("wearscale_faults_" + std::to_string(::getpid()));
// About 30 explicit steps on a 16² grid with a checkpoint every 10: every kind of write of a run
// (checkpoints, run.h5, CSV, XDMF, the plot's script, PNG, summary), in a fraction of a second.
const std::string args = "run '" + std::string(WEARSCALE_SOURCE_DIR) +
                         "/cases/pin_on_disc_si_oxide.toml' -j 1 --set scale.macro.grid=16 "
                         "--set scale.macro.distance=0.005 --set run.fft_planning=estimate "
                         "--set run.checkpoint_steps=10";

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
    if (f == "run.h5") {
      wearscale::H5Reader a(reference / f), b(got / f);  // complete: it opens, and holds the same series
      for (const char* s : {"/macro/series/distance", "/macro/series/friction", "/macro/final/pin"})
        EXPECT_EQ(a.read_series(s), b.read_series(s)) << where << ": " << s;
      continue;
    }
    EXPECT_TRUE(slurp(got / f) == slurp(reference / f)) << where << ": " << f << " differs from the complete file";
  }
  if (has_summary) {
    EXPECT_EQ(files, outputs_in(reference)) << where << ": a summary.json, but outputs are missing";
  }
}

long count_of(const fs::path& file) {
  long total = 0, n = 0;
  std::ifstream in(file);
  while (in >> n) total += n;  // one line per process that loaded the shim (wearscale, gnuplot, sh)
  return total;
}

nlohmann::json results_in(const fs::path& dir) { return nlohmann::json::parse(slurp(dir / "summary.json"))["results"]; }

// The run under the shim failing `op` from its N-th call on, for every N the run reaches.
void fail_each(const std::string& op, long max_points) {
  const auto reference = work / "reference";
  if (!fs::exists(reference / "out" / "summary.json")) {
    ASSERT_EQ(run_cli(args + " --out out", reference).status, 0);
  }
  const auto probe = work / ("count-" + op);
  fs::remove_all(probe);
  {
    ASSERT_EQ(run_cli(args + " --out out", probe, shim_env(probe, op, 0)).status, 0) << slurp(probe / "cli.stderr");
  }
  const long points = count_of(probe / "count");
  ASSERT_GT(points, 2) << op << ": the shim saw no call (not loaded?)";
  const long stride = std::max(1L, points / max_points);
  for (long at = 1; at <= points; at += stride) {
    const auto dir = work / (op + "-" + std::to_string(at));
    fs::remove_all(dir);
    const auto r = run_cli(args + " --out out", dir, shim_env(dir, op, at));
    const std::string where = op + " failing from call " + std::to_string(at) + " of " + std::to_string(points);
    ASSERT_NE(r.status, -1) << where << ": killed by a signal";
    EXPECT_EQ(r.status, 2) << where << ": " << r.err;
    EXPECT_THAT(r.err, HasSubstr("out/")) << where << ": the message names the file";
    EXPECT_THAT(r.err, ::testing::Not(HasSubstr("internal error"))) << where;
    expect_complete_outputs(dir / "out", reference / "out", where);
    // The disk works again: the run resumes (from its checkpoint, or afresh) to the undisturbed results.
    // (A run that failed before writing anything leaves no folder: it starts again.)
    const auto resumed = run_cli(args + (fs::exists(dir / "out") ? " --resume out" : " --out out"), dir);
    ASSERT_EQ(resumed.status, 0) << where << ", resumed: " << resumed.err;
    EXPECT_EQ(results_in(dir / "out"), results_in(reference / "out")) << where;
    EXPECT_EQ(outputs_in(dir / "out"), outputs_in(reference / "out")) << where;
    fs::remove_all(dir);
  }
}
}  // namespace

TEST(FaultInjection, TheDiskFillingUpAtEachWriteLeavesNoPartialOutputAndTheRunResumes) { fail_each("write", 40); }

TEST(FaultInjection, AnFsyncFailingAtEachCallLeavesNoPartialOutputAndTheRunResumes) { fail_each("fsync", 12); }

TEST(FaultInjection, ARenameFailingAtEachCallLeavesNoPartialOutputAndTheRunResumes) { fail_each("rename", 12); }
