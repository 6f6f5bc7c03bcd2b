// Job arrays without MPI: `--task K/N` runs the K-th of N shards of a sweep
// into one folder (the shards share its lock), `wearscale merge DIR` writes
// the table and summary once all are done: the outputs of the whole sweep run
// at once. Merge refuses, naming the missing tasks and their shards, while
// some are not done (nothing written); a resume under another N reruns only
// the runs not done; a bad --task and a shard of a single run are refused.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "oxide_sweep_case.hpp"
#include "same_outputs.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_shards_cli_");
const fs::path work = work_scratch.path();

// The oxide-thickness sweep of the pin-on-disc case, reduced to 5 short runs of 32² cells.
const std::string sweep_args =
    "run sweep.toml --set scale.macro.grid=32 --set scale.macro.distance=0.05 --set run.fft_planning=estimate -q -j 1";

CliResult run(const std::string& args) {
  write_oxide_sweep_case(work, "0, 5e-7, 1e-6, 3e-6, \"inf\"");
  return run_cli(args, work, "OMP_NUM_THREADS=1");
}

const fs::path& whole_sweep() {
  static const fs::path dir = [] {
    const auto r = run(sweep_args + " --out whole");
    EXPECT_EQ(r.status, 0) << r.err;
    return work / "whole";
  }();
  return dir;
}
}  // namespace

TEST(ShardsCli, ThreeShardsThenMergeGiveTheOutputsOfTheWholeSweep) {
  const auto& whole = whole_sweep();
  for (const char* task : {"1/3", "3/3"}) {
    const auto r = run(sweep_args + " --task " + task + " --out shards");
    ASSERT_EQ(r.status, 0) << task << "\n" << r.err;
  }
  EXPECT_FALSE(fs::exists(work / "shards" / "friction_vs_thickness.csv"));  // a shard writes no shared file
  EXPECT_TRUE(fs::exists(work / "shards" / "task-1-of-3.json"));
  // Shard 2/3 owes runs 2 and 5: merge refuses, naming them, and writes nothing.
  const auto refused = run("merge shards");
  EXPECT_EQ(refused.status, 2) << refused.err;
  EXPECT_THAT(refused.err, HasSubstr("2 of 5 tasks are not complete"));
  EXPECT_THAT(refused.err, HasSubstr("task 2 (thickness=5e-07: shard 2/3 has not run)"));
  EXPECT_THAT(refused.err, HasSubstr("task 5 (thickness=inf: shard 2/3 has not run)"));
  EXPECT_FALSE(fs::exists(work / "shards" / "summary.json"));
  EXPECT_FALSE(fs::exists(work / "shards" / "friction_vs_thickness.csv"));
  const auto r = run(sweep_args + " --task 2/3 --out shards");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto merged = run("merge shards --json");
  ASSERT_EQ(merged.status, 0) << merged.err;
  EXPECT_EQ(nlohmann::json::parse(merged.out)["sweep"]["runs"].size(), 5u);
  same_outputs::expect_same_outputs(whole, work / "shards", same_outputs::Timings::Ignored);
}

TEST(ShardsCli, AResumeUnderAnotherShardCountRunsOnlyTheRunsNotDone) {
  const auto& whole = whole_sweep();
  ASSERT_EQ(run(sweep_args + " --task 1/2 --out regrouped").status, 0);  // runs 1, 3, 5
  const auto kept = fs::last_write_time(work / "regrouped" / "thickness=0" / "summary.json");
  // Three shards now, resuming: 1/3 owns runs 1 and 4, of which only 4 is left; and so on.
  for (const char* task : {"1/3", "2/3", "3/3"}) {
    const auto r = run(sweep_args + " --task " + task + " --resume regrouped");
    ASSERT_EQ(r.status, 0) << task << "\n" << r.err;
  }
  EXPECT_EQ(fs::last_write_time(work / "regrouped" / "thickness=0" / "summary.json"), kept);  // not run again
  ASSERT_EQ(run("merge regrouped").status, 0);
  same_outputs::expect_same_outputs(whole, work / "regrouped", same_outputs::Timings::Ignored);
}

TEST(ShardsCli, ABadTaskOrAShardOfASingleRunIsRefused) {
  for (const char* task : {"0/3", "4/3", "2", "a/b", "1/0", "-1/2"}) {
    const auto r = run(sweep_args + " --task " + task + " --out bad_task");
    EXPECT_EQ(r.status, 2) << task << "\n" << r.err;
    EXPECT_THAT(r.err, HasSubstr("--task")) << task;
    EXPECT_THAT(r.err, HasSubstr("allowed: K/N")) << task;
    EXPECT_FALSE(fs::exists(work / "bad_task")) << task;
  }
  const auto single = run_cli("run '" WEARSCALE_SOURCE_DIR "/cases/hertz_pin.toml' --task 1/2 --out single -q", work);
  EXPECT_EQ(single.status, 2) << single.err;
  EXPECT_THAT(single.err, HasSubstr("not an ensemble"));
  EXPECT_FALSE(fs::exists(work / "single"));
  const auto nothing = run("merge " + (work / "sweep.toml").string());  // a file, not a folder
  EXPECT_EQ(nothing.status, 2);
  fs::create_directories(work / "empty");
  const auto empty = run("merge empty");
  EXPECT_EQ(empty.status, 2);
  EXPECT_THAT(empty.err, HasSubstr("no shard has run into this folder"));
}
