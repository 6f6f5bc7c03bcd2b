#include "wearscale/core/task_farm.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <chrono>
#include <cstring>
#include <exception>
#include <map>
#include <mutex>
#include <thread>

#ifdef WEARSCALE_MPI
#include <mpi.h>
#endif

#include "wearscale/core/log.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/core/progress.hpp"

namespace wearscale::mpi {

namespace {

using clock = std::chrono::steady_clock;

// Runs one task on this process alone; InputError and NumericalError fail the
// task, Interrupted leaves it not run, anything else passes (ends the job).
TaskResult run_one(std::size_t k, const std::function<std::string(std::size_t)>& task) {
  TaskResult r;
  r.rank = world_rank();
  r.threads = omp_get_max_threads();
  const auto start = clock::now();
  const Alone alone;
  try {
    r.text = task(k);
    r.status = TaskResult::Status::Done;
  } catch (const Interrupted& e) {
    r.status = TaskResult::Status::NotRun;
    r.text = e.what();
  } catch (const NumericalError& e) {
    r.status = TaskResult::Status::Failed;
    r.numerical = true;
    r.text = e.what();
  } catch (const InputError& e) {
    r.status = TaskResult::Status::Failed;
    r.text = e.what();
  }
  r.seconds = std::chrono::duration<double>(clock::now() - start).count();
  return r;
}

FarmOutcome count_outcome(std::vector<TaskResult> results) {
  FarmOutcome out;
  for (const auto& r : results) {
    out.failed += r.status == TaskResult::Status::Failed;
    out.not_run += r.status == TaskResult::Status::NotRun;
  }
  out.results = std::move(results);
  return out;
}

// The tasks in order on this thread (one rank, or alone).
FarmOutcome run_in_order(std::size_t count, const std::function<std::string(std::size_t)>& task,
                         const FarmOptions& options) {
  std::vector<TaskResult> results(count);
  Progress progress = options.show_progress ? Progress(options.label, static_cast<double>(count), "tasks")
                                            : Progress::silent(static_cast<double>(count));
  for (std::size_t k = 0; k < count; ++k) {
    if (options.stop && options.stop()) break;
    results[k] = run_one(k, task);
    progress.update(static_cast<double>(k + 1));
    if (results[k].status == TaskResult::Status::NotRun) break;
  }
  progress.finish();
  return count_outcome(std::move(results));
}

// The task kinds of this process, by name.
std::mutex g_kinds_mutex;
std::map<std::string, TaskKind>& task_kinds() {
  static std::map<std::string, TaskKind> kinds;
  return kinds;
}

TaskKind find_task_kind(const std::string& name) {
  std::lock_guard guard(g_kinds_mutex);
  const auto it = task_kinds().find(name);
  if (it == task_kinds().end()) throw std::logic_error("task farm: no task kind named '" + name + "' on this rank");
  return it->second;
}

// Rank 0 runs a study alone while the others serve it (ServedRun).
std::atomic<bool> g_served{false};

#ifdef WEARSCALE_MPI
constexpr int kTagResult = 7101;  // worker → rank 0: a result (or, first, a request for work)
constexpr int kTagTask = 7102;    // rank 0 → worker: the next task's index, or −1: no more
constexpr int kTagEnsemble = 7103;  // rank 0 → serving rank: an ensemble (kind, descriptions), or nothing: the end

// An ensemble on the wire: the kind's name and the descriptions, each after its length.
void append_sized(std::string& buf, const std::string& text) {
  const std::uint64_t n = text.size();
  buf.append(reinterpret_cast<const char*>(&n), sizeof n);
  buf.append(text);
}

std::string read_sized(const std::vector<char>& buf, std::size_t& at) {
  std::uint64_t n = 0;
  std::memcpy(&n, buf.data() + at, sizeof n);
  at += sizeof n;
  std::string text(buf.data() + at, buf.data() + at + n);
  at += n;
  return text;
}

// A result on the wire: index (−1: none yet), status, numerical, threads, seconds, text.
std::string encode(long long id, const TaskResult& r) {
  const int ints[3] = {static_cast<int>(r.status), r.numerical ? 1 : 0, r.threads};
  std::string buf;
  buf.append(reinterpret_cast<const char*>(&id), sizeof id);
  buf.append(reinterpret_cast<const char*>(ints), sizeof ints);
  buf.append(reinterpret_cast<const char*>(&r.seconds), sizeof r.seconds);
  buf.append(r.text);
  return buf;
}

long long decode(const std::vector<char>& buf, int source, TaskResult& r) {
  long long id = -1;
  int ints[3] = {};
  const char* p = buf.data();
  std::memcpy(&id, p, sizeof id), p += sizeof id;
  std::memcpy(ints, p, sizeof ints), p += sizeof ints;
  std::memcpy(&r.seconds, p, sizeof r.seconds), p += sizeof r.seconds;
  r.status = static_cast<TaskResult::Status>(ints[0]);
  r.numerical = ints[1] != 0;
  r.threads = ints[2];
  r.rank = source;
  r.text.assign(p, buf.data() + buf.size());
  return id;
}

void worker(const std::function<std::string(std::size_t)>& task) {
  std::string message = encode(-1, TaskResult{});
  for (;;) {
    MPI_Send(message.data(), static_cast<int>(message.size()), MPI_CHAR, 0, kTagResult, MPI_COMM_WORLD);
    long long id = -1;
    MPI_Recv(&id, 1, MPI_LONG_LONG, 0, kTagTask, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (id < 0) return;
    message = encode(id, run_one(static_cast<std::size_t>(id), task));
  }
}

// Rank 0: hands out the indices to whichever rank asks (its own thread
// included) and collects the results. The MPI calls stay on this thread
// (MPI_THREAD_FUNNELED); it polls for messages, sleeping between polls.
std::vector<TaskResult> dispatch(std::size_t count, const std::function<std::string(std::size_t)>& task,
                                 const FarmOptions& options) {
  std::vector<TaskResult> results(count);
  std::mutex mutex;
  std::size_t next = 0, done = 0;
  bool stopping = false;
  auto take = [&]() -> long long {
    std::lock_guard guard(mutex);
    if (stopping || next >= count) return -1;
    return static_cast<long long>(next++);
  };
  auto store = [&](long long id, TaskResult r) {
    std::lock_guard guard(mutex);
    results[static_cast<std::size_t>(id)] = std::move(r);
    ++done;
    if (results[static_cast<std::size_t>(id)].status == TaskResult::Status::NotRun) stopping = true;
  };
  // Rank 0's own share, on a thread with the rank's OpenMP threads.
  std::exception_ptr local_error;
  bool local_finished = false;
  const int threads = omp_get_max_threads();
  std::thread local([&] {
    omp_set_num_threads(threads);
    try {
      for (long long id = take(); id >= 0; id = take()) store(id, run_one(static_cast<std::size_t>(id), task));
    } catch (...) {
      local_error = std::current_exception();
    }
    std::lock_guard guard(mutex);
    local_finished = true;
  });
  Progress progress = options.show_progress ? Progress(options.label, static_cast<double>(count), "tasks")
                                            : Progress::silent(static_cast<double>(count));
  int workers = world_size() - 1;
  int idle_wait = 100;  // µs
  std::vector<char> buffer;
  for (;;) {
    if (options.stop && options.stop()) {
      std::lock_guard guard(mutex);
      stopping = true;
    }
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &flag, &status);
    if (flag != 0) {
      int bytes = 0;
      MPI_Get_count(&status, MPI_CHAR, &bytes);
      buffer.resize(static_cast<std::size_t>(bytes));
      MPI_Recv(buffer.data(), bytes, MPI_CHAR, status.MPI_SOURCE, kTagResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      TaskResult r;
      const long long id = decode(buffer, status.MPI_SOURCE, r);
      if (id >= 0) store(id, std::move(r));
      long long assign = take();
      MPI_Send(&assign, 1, MPI_LONG_LONG, status.MPI_SOURCE, kTagTask, MPI_COMM_WORLD);
      if (assign < 0) --workers;
    }
    bool finished = false;
    std::size_t so_far = 0;
    {
      std::lock_guard guard(mutex);
      finished = local_finished && workers == 0;
      so_far = done;
    }
    progress.update(static_cast<double>(so_far));
    if (finished) break;
    if (flag == 0) {
      std::lock_guard guard(mutex);
      if (local_finished && local_error) break;  // the job ends: main aborts it
    }
    // Idle: wait longer each time (0.1 ms up to 1 ms), so that a rank whose
    // tasks take seconds spends no core on asking; a message resets it.
    idle_wait = flag != 0 ? 100 : std::min(2 * idle_wait, 1000);
    if (flag == 0) std::this_thread::sleep_for(std::chrono::microseconds(idle_wait));
  }
  local.join();
  progress.finish();
  if (local_error) std::rethrow_exception(local_error);
  return results;
}
#endif

}  // namespace

void register_task_kind(const std::string& name, TaskKind kind) {
  std::lock_guard guard(g_kinds_mutex);
  task_kinds()[name] = std::move(kind);
}

ServedRun::ServedRun() : serving_(built_with_mpi() && size() > 1 && rank() == 0) { g_served = serving_; }

ServedRun::~ServedRun() {
#ifdef WEARSCALE_MPI
  if (serving_)
    for (int r = 1; r < world_size(); ++r) MPI_Send(nullptr, 0, MPI_CHAR, r, kTagEnsemble, MPI_COMM_WORLD);
#endif
  g_served = false;
}

bool ServedRun::active() { return g_served; }

void serve_ensembles() {
#ifdef WEARSCALE_MPI
  if (world_size() <= 1 || world_rank() == 0) return;
  std::vector<char> buffer;
  for (;;) {
    // Wait for rank 0's next ensemble, polling ever more slowly (0.1 to 20 ms):
    // a blocking receive would spin a core for as long as rank 0 computes alone.
    int flag = 0, wait = 100;
    MPI_Status status;
    for (;;) {
      MPI_Iprobe(0, kTagEnsemble, MPI_COMM_WORLD, &flag, &status);
      if (flag != 0) break;
      std::this_thread::sleep_for(std::chrono::microseconds(wait));
      wait = std::min(2 * wait, 20000);
    }
    int bytes = 0;
    MPI_Get_count(&status, MPI_CHAR, &bytes);
    buffer.resize(static_cast<std::size_t>(bytes));
    MPI_Recv(buffer.data(), bytes, MPI_CHAR, 0, kTagEnsemble, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (bytes == 0) return;  // the run is over
    std::size_t at = 0;
    const TaskKind kind = find_task_kind(read_sized(buffer, at));
    std::uint64_t count = 0;
    std::memcpy(&count, buffer.data() + at, sizeof count);
    at += sizeof count;
    std::vector<std::string> descriptions(count);
    for (auto& d : descriptions) d = read_sized(buffer, at);
    worker([&](std::size_t k) { return kind(descriptions[k]); });
  }
#endif
}

FarmOutcome farm_described(const std::string& name, const std::vector<std::string>& descriptions,
                           const FarmOptions& options) {
  const TaskKind kind = find_task_kind(name);
  const auto task = [&](std::size_t k) { return kind(descriptions[k]); };
  if (!ServedRun::active()) return run_in_order(descriptions.size(), task, options);
#ifdef WEARSCALE_MPI
  const auto start = clock::now();
  std::string message;
  append_sized(message, name);
  const std::uint64_t count = descriptions.size();
  message.append(reinterpret_cast<const char*>(&count), sizeof count);
  for (const auto& d : descriptions) append_sized(message, d);
  for (int r = 1; r < world_size(); ++r)
    MPI_Send(message.data(), static_cast<int>(message.size()), MPI_CHAR, r, kTagEnsemble, MPI_COMM_WORLD);
  auto out = count_outcome(dispatch(descriptions.size(), task, options));
  log::info("{}: {} tasks on {} ranks in {:.2f} s ({} failed, {} not run)", options.label, descriptions.size(),
            world_size(), std::chrono::duration<double>(clock::now() - start).count(), out.failed, out.not_run);
  return out;
#else
  return {};
#endif
}

FarmOutcome farm(std::size_t count, const std::function<std::string(std::size_t)>& task, const FarmOptions& options) {
  if (size() == 1 || !built_with_mpi()) return run_in_order(count, task, options);  // one rank, or alone
#ifdef WEARSCALE_MPI
  const auto start = clock::now();
  FarmOutcome out;
  if (world_rank() == 0) {
    out = count_outcome(dispatch(count, task, options));
    log::info("{}: {} tasks on {} ranks in {:.2f} s ({} failed, {} not run)", options.label, count, world_size(),
              std::chrono::duration<double>(clock::now() - start).count(), out.failed, out.not_run);
  } else {
    worker(task);
  }
  // Every rank learns how it went (rank 0's counts), so all end alike.
  out.failed = sum(world_rank() == 0 ? out.failed : 0LL);
  out.not_run = sum(world_rank() == 0 ? out.not_run : 0LL);
  return out;
#else
  return {};
#endif
}

}  // namespace wearscale::mpi
