// The finished tasks of a run's ensembles kept in its folder (task_store.hpp)
// and the farm that takes them: a kept task is found by its identity only, a
// damaged one runs again, a shard runs its share and stops, a merge takes
// every task or names those missing, each task logs to a file named after it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "scratch_dir.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/task_farm.hpp"
#include "wearscale/core/task_store.hpp"

namespace fs = std::filesystem;
using wearscale::mpi::FarmOptions;
using wearscale::mpi::TaskResult;
using wearscale::mpi::TaskStore;
using ::testing::HasSubstr;

namespace {
const ScratchDir scratch("wearscale_task_store_");

TaskResult done(const std::string& text) {
  TaskResult r;
  r.status = TaskResult::Status::Done;
  r.text = text;
  r.rank = 2;
  r.threads = 3;
  r.seconds = 1.5;
  return r;
}

// Five tasks whose result is "r<k>", counting how many ran.
struct Ensemble {
  std::vector<int> ran;
  FarmOptions options;
  Ensemble() {
    options.show_progress = false;
    options.identity = [](std::size_t k) { return fmt::format("case A task {}", k); };
    options.name = [](std::size_t k) { return fmt::format("seed {}", k + 1); };
  }
  wearscale::mpi::FarmOutcome run() {
    return wearscale::mpi::farm(5, [this](std::size_t k) {
      ran.push_back(static_cast<int>(k));
      return fmt::format("r{}", k);
    }, options);
  }
};
}  // namespace

TEST(TaskStore, AKeptResultIsFoundByItsIdentityOnlyWithWhereAndHowLongItRan) {
  const TaskStore store(scratch.path() / "identity" / "tasks");
  EXPECT_FALSE(store.find("a"));
  store.keep("a", done(std::string("bytes\0with a zero\n", 18)));
  const auto found = store.find("a");
  ASSERT_TRUE(found);
  EXPECT_EQ(found->text, std::string("bytes\0with a zero\n", 18));
  EXPECT_EQ(found->rank, 2);
  EXPECT_EQ(found->threads, 3);
  EXPECT_EQ(found->seconds, 1.5);
  EXPECT_FALSE(store.find("b"));
  EXPECT_TRUE(TaskStore::holds_tasks(store.dir()));
  TaskResult failed;
  failed.status = TaskResult::Status::Failed;
  store.keep("c", failed);  // only finished tasks are kept
  EXPECT_FALSE(store.find("c"));
}

TEST(TaskStore, ADamagedResultIsNotTakenAndTheTaskRunsAgain) {
  const TaskStore store(scratch.path() / "damaged" / "tasks");
  store.keep("a", done("the result"));
  for (const auto& e : fs::directory_iterator(store.dir())) {
    std::fstream f(e.path(), std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(-3, std::ios::end);
    f.put('X');  // one byte of the result changed
  }
  EXPECT_FALSE(store.find("a"));
}

TEST(TaskStore, AFarmKeepsEachFinishedTaskAndARerunTakesThemInsteadOfRunning) {
  const TaskStore store(scratch.path() / "rerun" / "tasks", TaskStore::Mode::Keep, 1, 1, "case A");
  Ensemble first;
  const auto a = first.run();
  EXPECT_EQ(first.ran.size(), 5u);
  EXPECT_EQ(TaskStore::case_of(store.dir()), "case A");
  Ensemble second;
  const auto b = second.run();
  EXPECT_TRUE(second.ran.empty());
  ASSERT_EQ(b.results.size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(b.results[k].text, a.results[k].text);
  // Each task wrote its log, named after it.
  EXPECT_TRUE(fs::exists(store.log_path("case A task 2", "seed 3")));
  EXPECT_THAT(store.log_path("case A task 2", "seed 3").filename().string(), ::testing::StartsWith("seed_3-"));
}

// Rank 0 keeps its own results and those its workers send from two threads
// at once: the first two of a run both find the case's mark missing. Every
// result is kept and the mark written, whichever thread comes first (the
// first keeps of a run raced on the mark's temporary file: an MPI wear map
// ended with status 2 in CI, "cannot open tasks/.case.txt.partial-<pid>").
TEST(TaskStore, TwoThreadsKeepingTheFirstResultsOfARunAtOnceKeepBothAndTheCase) {
  for (int round = 0; round < 200; ++round) {
    const TaskStore store(scratch.path() / fmt::format("race{}", round) / "tasks", TaskStore::Mode::Keep, 1, 1,
                          "case R");
    std::atomic<int> ready{0};
    std::vector<std::string> errors(2);
    auto keep = [&](int t) {
      ++ready;
      while (ready.load() < 2) {
      }
      try {
        store.keep(fmt::format("task {}", t), done(fmt::format("r{}", t)));
      } catch (const std::exception& e) {
        errors[static_cast<std::size_t>(t)] = e.what();
      }
    };
    std::thread a(keep, 0), b(keep, 1);
    a.join();
    b.join();
    ASSERT_EQ(errors[0] + errors[1], "") << "round " << round;
    ASSERT_EQ(TaskStore::case_of(store.dir()), "case R") << "round " << round;
    ASSERT_TRUE(store.find("task 0") && store.find("task 1")) << "round " << round;
  }
}

TEST(TaskStore, AShardRunsItsShareThenStopsAndAMergeTakesEveryTaskOrNamesTheMissing) {
  const fs::path dir = scratch.path() / "shards" / "tasks";
  {
    const TaskStore shard(dir, TaskStore::Mode::Shard, 2, 3);  // tasks 1 and 4
    Ensemble e;
    EXPECT_THROW(e.run(), wearscale::mpi::ShardDone);
    EXPECT_EQ(e.ran, (std::vector<int>{1, 4}));
  }
  {
    TaskStore merge(dir, TaskStore::Mode::Assemble);
    merge.owner = [](std::size_t k) { return fmt::format("shard {}/3 has not run", k % 3 + 1); };
    Ensemble e;
    try {
      e.run();
      ADD_FAILURE() << "a merge with tasks missing went through";
    } catch (const wearscale::InputError& error) {
      EXPECT_THAT(error.what(), HasSubstr("3 of 5 tasks are not done: seed 1 (shard 1/3 has not run); seed 3 "
                                          "(shard 3/3 has not run); seed 4 (shard 1/3 has not run)"));
    }
    EXPECT_TRUE(e.ran.empty());  // a merge computes nothing
  }
  {
    const TaskStore shard(dir, TaskStore::Mode::Shard, 1, 3);  // tasks 0 and 3; task 2 is still missing
    Ensemble e;
    EXPECT_THROW(e.run(), wearscale::mpi::ShardDone);
  }
  {
    const TaskStore shard(dir, TaskStore::Mode::Shard, 3, 3);  // task 2, the last: the ensemble is whole
    Ensemble e;
    EXPECT_EQ(e.run().results.size(), 5u);
    EXPECT_EQ(e.ran, (std::vector<int>{2}));
  }
  const TaskStore merge(dir, TaskStore::Mode::Assemble);
  Ensemble e;
  const auto out = e.run();
  EXPECT_TRUE(e.ran.empty());
  ASSERT_EQ(out.results.size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(out.results[k].text, fmt::format("r{}", k));
}
