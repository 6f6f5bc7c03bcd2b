#pragma once
// A task farm over the ranks of an MPI job: the independent tasks of an
// ensemble (the runs of a sweep) handed out one at a time, so tasks that
// differ 10× in cost balance over the ranks. Rank 0 hands out the indices
// (dynamically, the next to whichever rank asks) and also computes on a
// thread of its own; every rank runs a task on its own (mpi::Alone: the
// task's study sees one rank and makes no collective call) with the threads
// the rank is given (-j, OMP_NUM_THREADS); a task's result (a short text,
// e.g. the run's summary as JSON) comes back to rank 0, which alone writes the
// ensemble's shared outputs. Serial (one rank, or a build without MPI): the
// tasks run in order in the calling thread.
//
// With a TaskStore (task_store.hpp) the farm runs only the tasks it does not
// hold: a shard's share, or what a killed run had not finished.
//
// A task that throws an InputError (an OutputError too) or a NumericalError
// fails that task, which is marked and reported, not the job; any other
// exception ends the job (mpi::abort through main), and a rank that dies
// ends it too (the launcher's doing), so no rank waits forever.
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/mpi.hpp"

namespace wearscale::mpi {

struct TaskResult {
  enum class Status { Done, Failed, NotRun };
  Status status = Status::NotRun;  ///< NotRun: the farm stopped (SIGINT) before it
  std::string text;                ///< Done: what the task returned; Failed: the error message
  bool numerical = false;          ///< Failed by a NumericalError (else by an InputError)
  bool output = false;             ///< Failed by an OutputError: an output that cannot be written (a full disk)
  int rank = 0;                    ///< the rank that ran it
  int threads = 1;                 ///< the OpenMP threads it ran with
  double seconds = 0.0;            ///< its wall time
};

struct FarmOptions {
  std::string label = "tasks";     ///< the progress line's label (rank 0, on a terminal only)
  bool show_progress = true;       ///< false: no progress line (a farm inside a run that shows its own)
  std::function<bool()> stop;      ///< no task is handed out once it returns true (SIGINT)
  /// What determines task k's result (e.g. the case and the seed). With a
  /// TaskStore on the calling thread (rank 0 of a run), each result is kept
  /// there as it finishes and a kept one is taken instead of running the task
  /// again (a resumed run, a shard, a merge). Empty: nothing kept.
  /// farm_described's default: the kind and the description.
  std::function<std::string(std::size_t)> identity;
  /// Task k in messages (e.g. "seed 3"); default "task k+1".
  std::function<std::string(std::size_t)> name;
  /// Whether rank 0 computes tasks on a thread of its own beside handing
  /// them out. False for tasks that make MPI calls of their own (a LAMMPS
  /// instance on MPI_COMM_SELF): under MPI_THREAD_FUNNELED only a rank's main
  /// thread may, so rank 0 then only hands out and the other ranks compute.
  bool root_computes = true;
};

/// What a farm did, on every rank (rank 0's figures, shared with all).
struct FarmOutcome {
  std::vector<TaskResult> results;  ///< rank 0: one per task, in task order; other ranks: empty
  long long failed = 0;             ///< tasks that failed (every rank)
  long long not_run = 0;            ///< tasks not started because the farm stopped (every rank)
};

/// Runs task(k) for every k in [0, count) over the ranks. Collective: every
/// rank calls it with the same count and an equivalent task. `task` returns
/// the result's text (any bytes). Inside a task (mpi::Alone) a farm runs its
/// tasks in order on the calling thread: an ensemble within an ensemble's
/// task stays on the rank that runs it.
FarmOutcome farm(std::size_t count, const std::function<std::string(std::size_t)>& task,
                 const FarmOptions& options = {});

// --- Ensembles met by a study that rank 0 runs alone -------------------------
//
// Some studies are one chain of work with ensembles inside it (the junction
// runs of nano/dem within a pipeline): rank 0 runs the study alone, the other
// ranks serve it, and each ensemble rank 0 meets is farmed over all of them.
// Its tasks travel as descriptions (bytes a task kind turns into a result), so
// a serving rank needs nothing of the study but the kinds registered.

/// A kind of task: its description in, its result out (InputError or
/// NumericalError fail the task, as in farm()).
using TaskKind = std::function<std::string(const std::string& description)>;

/// Registers a kind under `name` (again: replaced); every rank registers the
/// same kinds (e.g. when its study is prepared).
void register_task_kind(const std::string& name, TaskKind kind);

/// Rank 0 of a job (not alone), while one lives: the other ranks serve (serve_ensembles()), and
/// farm_described() uses them. It runs the study alone (mpi::Alone), so the
/// study takes its serial path elsewhere. Its end (or rank 0's failure, which
/// aborts the job) releases the serving ranks.
class ServedRun {
 public:
  ServedRun();
  ~ServedRun();
  ServedRun(const ServedRun&) = delete;
  ServedRun& operator=(const ServedRun&) = delete;
  /// A ServedRun lives on this rank and there are ranks to serve it.
  static bool active();

 private:
  bool serving_;  // this rank drives the job's ranks (not a task of a farm, not alone); set before alone_
  Alone alone_;
};

/// The other ranks: run the ensembles rank 0 farms out until its ServedRun
/// ends. Waits without spinning (a rank that waits for hours costs no core).
void serve_ensembles();

/// What determines the result of a described task (its identity in a TaskStore).
std::string described_identity(const std::string& kind, const std::string& description);

/// Rank 0 under a ServedRun: the tasks of kind `kind`, one per description,
/// over every rank (rank 0 too, on a thread), dynamically; results as farm()'s.
/// Without a ServedRun (serial, or alone): the tasks in order on this thread.
FarmOutcome farm_described(const std::string& kind, const std::vector<std::string>& descriptions,
                           const FarmOptions& options = {});

/// Some tasks of an ensemble failed (each marked in its table); thrown on
/// every rank together once the ensemble's outputs are written, so the job
/// ends with status 1 (exit_numerical_failure) without an abort. `speaks` on
/// rank 0 only, whose message says which tasks failed and why.
class TasksFailed : public std::runtime_error {
 public:
  /// `output`: a task failed because an output could not be written (a full disk, a read-only folder):
  /// the job ends as a serial run would, with status 2, not 1.
  TasksFailed(const std::string& message, bool speaks, bool output = false)
      : std::runtime_error(message), speaks_(speaks), output_(output) {}
  bool speaks() const { return speaks_; }
  bool output() const { return output_; }

 private:
  bool speaks_, output_;
};

}  // namespace wearscale::mpi
