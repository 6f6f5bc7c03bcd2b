// Job arrays over the ensembles inside one run (no MPI): `--task K/N` computes
// the K-th of N shares of a rough wear map's surfaces, or of nano/dem's
// junction runs, keeping them in the run's folder (tasks/); `wearscale merge`
// then writes the run's outputs, equal to the run made at once. Merge refuses,
// naming the missing tasks and the shards that owe them, and writes nothing;
// a shard writes none of the run's outputs; a run stopped by a signal keeps
// its finished tasks, and its resume computes only the others.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "same_outputs.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_ensemble_shards_cli_");
const fs::path work = work_scratch.path();

CliResult run(const std::string& args) { return run_cli(args, work, "OMP_NUM_THREADS=1"); }

// Fig. 5.6 reduced: three 64² surfaces (the ensemble's tasks), 4 × 4 pixels.
const std::string wearmap_args = "wearmap rough --n 64 --seeds 3 --n-loads 4 --n-dstar 4 -q";

// Fig. 7.2's junction runs reduced: a 12 × 6 cell, two sizes at two pressures, a short slide, no cache.
const std::string junction_args = "run '" WEARSCALE_SOURCE_DIR "/cases/junction_sio2.toml' --set scale.nano.length=12 "
                                  "--set scale.nano.height=6 --set scale.nano.cache=false "
                                  "--set 'scale.nano.contact_ratios=[0.5, 1]' --set 'scale.nano.pressures=[1e9, 4e9]' "
                                  "--set scale.nano.sliding_distance=0.2 -q";

std::size_t kept_tasks(const fs::path& dir) {
  std::size_t n = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir / "tasks", ec)) n += e.path().extension() == ".task" ? 1 : 0;
  return n;
}
}  // namespace

TEST(EnsembleShardsCli, TwoShardsOfAWearMapsSurfacesThenMergeGiveTheMapRunAtOnce) {
  ASSERT_EQ(run(wearmap_args + " --out wearmap_whole").status, 0);
  const auto first = run(wearmap_args + " --task 1/2 --out wearmap_shards");  // seeds 1 and 3
  ASSERT_EQ(first.status, 0) << first.err;
  EXPECT_TRUE(fs::exists(work / "wearmap_shards" / "task-1-of-2.json"));
  EXPECT_EQ(kept_tasks(work / "wearmap_shards"), 2u);
  EXPECT_FALSE(fs::exists(work / "wearmap_shards" / "summary.json"));  // a shard writes none of the run's outputs
  EXPECT_FALSE(fs::exists(work / "wearmap_shards" / "wearmap_rough.h5"));
  // Seed 2 is shard 2/2's: merge refuses, naming it, and writes nothing.
  const auto refused = run("merge wearmap_shards");
  EXPECT_EQ(refused.status, 2) << refused.err;
  EXPECT_THAT(refused.err, HasSubstr("1 of 3 tasks are not done: seed 2 (shard 2/2 has not run)"));
  EXPECT_FALSE(fs::exists(work / "wearmap_shards" / "summary.json"));
  EXPECT_FALSE(fs::exists(work / "wearmap_shards" / "wearmap_rough.csv"));
  const auto second = run(wearmap_args + " --task 2/2 --out wearmap_shards");
  ASSERT_EQ(second.status, 0) << second.err;
  EXPECT_EQ(kept_tasks(work / "wearmap_shards"), 3u);
  const auto merged = run("merge wearmap_shards");
  ASSERT_EQ(merged.status, 0) << merged.err;
  same_outputs::expect_same_outputs(work / "wearmap_whole", work / "wearmap_shards", same_outputs::Timings::Ignored);
  EXPECT_FALSE(fs::exists(work / "wearmap_shards" / "tasks"));  // complete: the kept tasks go
}

TEST(EnsembleShardsCli, ThreeShardsOfTheJunctionRunsThenMergeGiveTheLawRunAtOnce) {
  ASSERT_EQ(run(junction_args + " --out junction_whole").status, 0);
  for (const char* task : {"1/3", "3/3"}) {
    const auto r = run(junction_args + " --task " + task + " --out junction_shards");
    ASSERT_EQ(r.status, 0) << task << "\n" << r.err;
  }
  EXPECT_EQ(kept_tasks(work / "junction_shards"), 3u);  // 1/3 owns runs 1 and 4, 3/3 run 3
  const auto refused = run("merge junction_shards");
  EXPECT_EQ(refused.status, 2) << refused.err;
  EXPECT_THAT(refused.err, HasSubstr("1 of 4 tasks are not done"));
  EXPECT_THAT(refused.err, HasSubstr("(shard 2/3 has not run)"));
  EXPECT_FALSE(fs::exists(work / "junction_shards" / "summary.json"));
  ASSERT_EQ(run(junction_args + " --task 2/3 --out junction_shards").status, 0);
  const auto merged = run("merge junction_shards");
  ASSERT_EQ(merged.status, 0) << merged.err;
  same_outputs::expect_same_outputs(work / "junction_whole", work / "junction_shards", same_outputs::Timings::Ignored);
}

TEST(EnsembleShardsCli, AFreshRunRefusesAFolderHoldingAnUnfinishedRunsTasks) {
  ASSERT_EQ(run(wearmap_args + " --task 1/3 --out unfinished").status, 0);
  const auto fresh = run(wearmap_args + " --out unfinished");
  EXPECT_EQ(fresh.status, 2) << fresh.err;
  EXPECT_THAT(fresh.err, HasSubstr("holds the finished tasks of an unfinished run"));
  EXPECT_EQ(kept_tasks(work / "unfinished"), 1u);  // nothing lost
  // Resumed (no shard): seed 1 is taken, seeds 2 and 3 computed; the map is the one run at once.
  ASSERT_EQ(run(wearmap_args + " --out wearmap_whole_too").status, 0);
  const auto resumed = run(wearmap_args + " --resume unfinished");
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  same_outputs::expect_same_outputs(work / "wearmap_whole_too", work / "unfinished", same_outputs::Timings::Ignored);
}

TEST(EnsembleShardsCli, AShardOfARunWithoutAnEnsembleIsRefused) {
  const auto r = run("run '" WEARSCALE_SOURCE_DIR "/cases/hertz_pin.toml' --task 1/2 --out no_ensemble -q");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("not an ensemble"));
  EXPECT_FALSE(fs::exists(work / "no_ensemble"));
}
