#pragma once
// The MPI layer: one process among the ranks of an `mpirun -np P` or `srun`
// job. The C++ side owns MPI: main() holds a Session, which initialises MPI
// when the process was started by a launcher (Open MPI, PMI/PMIx, Slurm) and
// finalises it at exit; a process started on its own stays serial (rank 0 of
// 1, no MPI call), and so does a build without WEARSCALE_MPI. A rank that
// fails calls abort(): the whole job ends, no rank waits for it forever.
#include <cstddef>
#include <functional>
#include <span>
#include <string>

#include "wearscale/core/errors.hpp"

namespace wearscale::mpi {

/// Built with MPI (WEARSCALE_MPI).
bool built_with_mpi();

/// Initialises MPI (threads: funnelled, OpenMP inside a rank) if a launcher
/// started this process; MPI_Finalize when it goes out of scope.
class Session {
 public:
  Session(int& argc, char**& argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

/// True between a Session's initialisation of MPI and its end.
bool active();
/// This process's rank in the job and the number of ranks (0 and 1 when serial).
int rank();
int size();
inline bool is_root() { return rank() == 0; }

/// The job as launched, whatever Alone says: for the task farm, and abort().
int world_rank();
int world_size();
/// The ranks of the job on this node (this one included; 1 when serial).
int node_size();

/// The OpenMP threads a rank takes when neither -j nor OMP_NUM_THREADS says:
/// the cores this process may run on shared among the ranks of its node (at
/// least 1), so P ranks on a node do not start P teams of all its cores each
/// (spinning teams on shared cores slow each other down tenfold). 0 when
/// serial: the OpenMP default (every core) stands.
int default_threads_per_rank();

/// While one lives, this process computes on its own (a task of the farm,
/// core/task_farm.hpp): active() is false, rank() 0 and size() 1, so a study
/// run as a task takes its serial path and makes no collective call. The
/// farm itself talks to the other ranks through world_rank()/world_size().
class Alone {
 public:
  Alone();
  ~Alone();
  Alone(const Alone&) = delete;
  Alone& operator=(const Alone&) = delete;

 private:
  bool was_;
};

/// Ends every rank of the job with `code` (MPI_Abort); std::exit(code) when serial.
[[noreturn]] void abort(int code);
/// Waits for every rank.
void barrier();

/// Sums over the ranks, the result on every rank (MPI_Allreduce; the ranks'
/// parts added in rank order, so the result does not depend on timing).
double sum(double local);
void sum(std::span<double> values);
long long sum(long long local);
double max(double local);
/// The largest (smallest) of the ranks' values, element by element, on every rank (MPI_Allreduce).
void max(std::span<double> values);
void min(std::span<double> values);

/// Gathers every rank's `local` values, in rank order, into `all` on rank 0
/// (whose size must be the total; ignored on the other ranks): a field
/// distributed in slabs of rows becomes the whole field on rank 0. Serial: a copy.
void gather(std::span<const double> local, std::span<double> all);

/// The reverse of gather: rank 0's `all` (ignored on the other ranks) split in
/// rank order, each rank receiving as many values as its `local` holds (the
/// counts must add up to all.size()). What rank 0 alone worked out for every
/// rank's rows, e.g. which micro-contact each of their clusters' pieces joins.
/// Serial: a copy.
void scatter(std::span<const double> all, std::span<double> local);

/// Rank 0's `values` (the same count on every rank) and `text` on every rank
/// (MPI_Bcast); serial: unchanged. What rank 0 alone decided, e.g. where in a
/// file it laid out the fields every rank then writes.
void broadcast(std::span<double> values);
void broadcast(std::string& text);

/// The refusal of a job that every rank reached together (refuse_together):
/// every rank ends with status 2 and no rank needs MPI_Abort. `speaks` on the
/// one rank that prints the message (the lowest that refused); the others
/// carry an empty message and print nothing.
class JointRefusal : public InputError {
 public:
  JointRefusal(const std::string& message, bool speaks) : InputError(message), speaks_(speaks) {}
  bool speaks() const { return speaks_; }

 private:
  bool speaks_;
};

/// A stop every rank reached at the same point of the same collective work
/// (a slab solve sums the ranks' answers to "stop?" every iteration): the job
/// ends with the stop's status on every rank, no rank aborts the others.
class JointInterruption : public Interrupted {
 public:
  explicit JointInterruption(const std::string& message) : Interrupted(message) {}
};

/// Runs `checks` on every rank (collective) and agrees on the outcome: when an
/// InputError is thrown on any rank, every rank throws a JointRefusal (the
/// message of the lowest rank that refused, spoken there only). Other
/// exceptions pass through (a rank that fails otherwise ends the job through
/// abort()). Serial: runs `checks`, its InputError unchanged.
void refuse_together(const std::function<void()>& checks);

}  // namespace wearscale::mpi
