#pragma once
// The finished tasks of a run's ensembles (the surfaces of a rough wear map,
// the junction runs of nano/dem), kept in the run's folder (tasks/) as each
// finishes. With it
//   - a run stopped or killed in the middle of an ensemble resumes (--resume,
//     under any number of ranks) with only the tasks it had not finished;
//   - a shard (--task K/N, a job array's task) computes its share of every
//     ensemble of the run and stops there;
//   - `wearscale merge` assembles the run from what its shards kept, and
//     refuses, naming them, while tasks are missing.
// A task is found by its identity (every input that determines its result:
// the kind and description of a described task), so a task of another case
// is never taken for it. One file per task (a header line, then the result's
// bytes), written atomically by rank 0 alone; each task's log in logs/.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

namespace wearscale::mpi {

struct TaskResult;

class TaskStore {
 public:
  enum class Mode {
    Keep,      ///< tasks found are taken, the others run and are kept
    Shard,     ///< as Keep, but only this shard's tasks run; an ensemble that lacks others' stops the run (ShardDone)
    Assemble,  ///< every task must be found (merge): none runs, a missing one is refused by name
  };

  /// The store of folder `dir` for the farms this thread starts, until it is
  /// destroyed (rank 0 of a run). Shard: the K-th (1-based) of N shards owns
  /// the tasks k (0-based, in ensemble order) with k mod N = K − 1.
  /// `case_id` (e.g. the case's fingerprint) goes to dir/case.txt with the
  /// first task kept: the folder is made only when a task is kept.
  explicit TaskStore(std::filesystem::path dir, Mode mode = Mode::Keep, std::size_t shard = 1, std::size_t shards = 1,
                     std::string case_id = {});
  ~TaskStore();
  TaskStore(const TaskStore&) = delete;
  TaskStore& operator=(const TaskStore&) = delete;

  /// The store installed on this thread, or null.
  static TaskStore* current();

  Mode mode() const { return mode_; }
  const std::filesystem::path& dir() const { return dir_; }
  /// This shard runs task k of an ensemble.
  bool owns(std::size_t k) const { return k % shards_ + 1 == shard_; }
  std::size_t shard() const { return shard_; }
  std::size_t shards() const { return shards_; }

  /// The kept result of the task with this identity (status Done), if any.
  std::optional<TaskResult> find(const std::string& identity) const;
  /// Keeps a finished task's result (Done only; others are run again).
  void keep(const std::string& identity, const TaskResult& result) const;
  /// Keeps the result `text` of a task finished here, outside the farm (rank 0, one thread).
  void keep(const std::string& identity, std::string text, double seconds = 0.0) const;
  /// Where the task with this identity and name ("seed 3") writes its log:
  /// logs/ beside tasks/, a file named after the task; it stays with the outputs.
  std::filesystem::path log_path(const std::string& identity, const std::string& name) const;

  /// For Assemble: who owes task k (e.g. "shard 2/3 has not run"), for the refusal.
  std::function<std::string(std::size_t)> owner;

  /// The run is complete: its tasks are no longer needed (the folder goes).
  void discard() const;
  /// `dir` holds the tasks of a run that has not completed.
  static bool holds_tasks(const std::filesystem::path& dir);
  /// The case `dir`'s tasks were kept for ("" if none).
  static std::string case_of(const std::filesystem::path& dir);

 private:
  std::filesystem::path file_of(const std::string& identity, const char* extension) const;
  std::filesystem::path dir_;
  Mode mode_;
  std::size_t shard_, shards_;
  std::string case_id_;
  TaskStore* previous_;
};

/// A shard has run its tasks of an ensemble whose other tasks no shard has
/// kept yet: the run stops there, its share done (not an error: exit 0).
class ShardDone : public std::runtime_error {
 public:
  explicit ShardDone(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace wearscale::mpi
