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
#include "wearscale/core/task_store.hpp"
#include "wearscale/core/utc_time.hpp"

#include <fmt/format.h>
#include <filesystem>

namespace wearscale::mpi {

namespace {

using clock = std::chrono::steady_clock;

// Runs one task on this process alone; InputError and NumericalError fail the
// task, Interrupted leaves it not run, anything else passes (ends the job).
// `log`: the task's own log file ("" none), on whichever rank runs it.
TaskResult run_one(std::size_t k, const std::function<std::string(std::size_t)>& task, const std::string& log = {}) {
  TaskResult r;
  r.rank = world_rank();
  r.threads = omp_get_max_threads();
  const auto start = clock::now();
  const Alone alone;
  std::optional<log::TaskLog> task_log;
  if (!log.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(log).parent_path(), ec);
    task_log.emplace(log);
    log::task_note(fmt::format("task started on rank {} of {}, {} thread(s), {}", r.rank, world_size(), r.threads,
                               utc_now()));
  }
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
  } catch (const OutputError& e) {
    r.status = TaskResult::Status::Failed;
    r.output = true;
    r.text = e.what();
  } catch (const InputError& e) {
    r.status = TaskResult::Status::Failed;
    r.text = e.what();
  }
  r.seconds = std::chrono::duration<double>(clock::now() - start).count();
  if (task_log)
    log::task_note(fmt::format("task {} in {:.3f} s{}", r.status == TaskResult::Status::Done ? "done" : r.status == TaskResult::Status::Failed ? "failed" : "stopped", r.seconds,
                               r.status == TaskResult::Status::Done ? std::string() : ": " + r.text));
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

// Which tasks of an ensemble run (decided on rank 0): with a TaskStore on the
// calling thread, those it does not hold (of this shard); the ones it holds
// are taken as they were. Each task to run is a slot 0 … todo.size() − 1.
struct Share {
  const TaskStore* store = nullptr;
  std::vector<std::string> identities;  // with a store: one per task
  std::vector<TaskResult> results;      // one per task; the kept ones Done
  std::vector<std::size_t> todo;        // the tasks to run, in ensemble order
  std::vector<std::string> logs;        // per slot: its log file
  std::vector<std::size_t> elsewhere;   // Shard: other shards' tasks not kept yet

  // A slot finished (rank 0): its result kept at once, so that a kill loses only unfinished tasks.
  void done(std::size_t slot, const TaskResult& r) {
    if (store != nullptr) store->keep(identities[todo[slot]], r);
  }
};

std::string task_name(const FarmOptions& options, std::size_t k) {
  return options.name ? options.name(k) : fmt::format("task {}", k + 1);
}

Share share_of(std::size_t count, const FarmOptions& options) {
  Share s;
  s.results.resize(count);
  const TaskStore* store = TaskStore::current();
  if (store != nullptr && options.identity) s.store = store;
  std::vector<std::size_t> missing;
  std::size_t found = 0;
  for (std::size_t k = 0; k < count; ++k) {
    if (s.store == nullptr) {
      s.todo.push_back(k);
      s.logs.emplace_back();
      continue;
    }
    s.identities.push_back(options.identity(k));
    const std::string& id = s.identities.back();
    if (auto kept = store->find(id)) {
      s.results[k] = std::move(*kept);
      ++found;
    } else if (store->mode() == TaskStore::Mode::Assemble) {
      missing.push_back(k);
    } else if (store->mode() == TaskStore::Mode::Shard && !store->owns(k)) {
      s.elsewhere.push_back(k);
    } else {
      s.todo.push_back(k);
      s.logs.push_back(store->log_path(id, task_name(options, k)).string());
    }
  }
  if (!missing.empty()) {
    std::vector<std::string> names;
    for (const auto k : missing)
      names.push_back(store->owner ? fmt::format("{} ({})", task_name(options, k), store->owner(k)) : task_name(options, k));
    throw InputError(fmt::format("{}: {} of {} tasks are not done: {}", options.label, missing.size(), count,
                                 fmt::join(names, "; ")));
  }
  if (found > 0)
    log::info("{}: {} of {} tasks taken from {} (finished before)", options.label, found, count, store->dir().string());
  return s;
}

// The ensemble's outcome (rank 0) from its share and the slots' results. A
// shard whose ensemble still lacks other shards' tasks stops the run here.
FarmOutcome finish(Share& s, std::vector<TaskResult> slots, const FarmOptions& options) {
  for (std::size_t t = 0; t < slots.size(); ++t) s.results[s.todo[t]] = std::move(slots[t]);
  for (const auto k : s.elsewhere) s.results[k].text = "another shard's task";
  FarmOutcome out = count_outcome(std::move(s.results));
  if (s.elsewhere.empty()) return out;
  out.not_run -= static_cast<long long>(s.elsewhere.size());
  if (out.not_run > 0) throw Interrupted(fmt::format("{}: stopped by a signal", options.label));
  std::vector<std::string> failed;
  bool output = false;
  for (const auto k : s.todo)
    if (out.results[k].status == TaskResult::Status::Failed) {
      failed.push_back(fmt::format("{}: {}", task_name(options, k), out.results[k].text));
      output = output || out.results[k].output;
    }
  if (!failed.empty())
    throw TasksFailed(fmt::format("{}: {} of this shard's {} tasks failed: {}", options.label, failed.size(),
                                  s.todo.size(), fmt::join(failed, "; ")),
                      true, output);
  throw ShardDone(fmt::format("{}: this shard's {} task(s) done, {} left to the other shards", options.label,
                              s.todo.size(), s.elsewhere.size()));
}

// The slots in order on this thread (one rank, or alone).
std::vector<TaskResult> run_in_order(Share& s, const std::function<std::string(std::size_t)>& task,
                                     const FarmOptions& options) {
  const std::size_t count = s.todo.size();
  std::vector<TaskResult> results(count);
  Progress progress = options.show_progress ? Progress(options.label, static_cast<double>(count), "tasks")
                                            : Progress::silent(static_cast<double>(count));
  for (std::size_t t = 0; t < count; ++t) {
    if (options.stop && options.stop()) break;
    results[t] = run_one(s.todo[t], task, s.logs[t]);
    s.done(t, results[t]);
    progress.update(static_cast<double>(t + 1));
    if (results[t].status == TaskResult::Status::NotRun) break;
  }
  progress.finish();
  return results;
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
  const int ints[3] = {static_cast<int>(r.status), r.numerical ? 1 : r.output ? 2 : 0, r.threads};
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
  r.numerical = ints[1] == 1;
  r.output = ints[1] == 2;
  r.threads = ints[2];
  r.rank = source;
  r.text.assign(p, buf.data() + buf.size());
  return id;
}

// A serving rank: asks for slots and runs them (each with its log, if any) until told there are no more.
void worker(const std::function<std::string(std::size_t)>& task, const std::vector<std::string>& logs) {
  std::string message = encode(-1, TaskResult{});
  for (;;) {
    MPI_Send(message.data(), static_cast<int>(message.size()), MPI_CHAR, 0, kTagResult, MPI_COMM_WORLD);
    long long id = -1;
    MPI_Recv(&id, 1, MPI_LONG_LONG, 0, kTagTask, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (id < 0) return;
    const auto slot = static_cast<std::size_t>(id);
    message = encode(id, run_one(slot, task, slot < logs.size() ? logs[slot] : std::string()));
  }
}

// The slots (and their logs) from rank 0 to every rank: the same list everywhere.
void broadcast_slots(std::vector<std::size_t>& todo, std::vector<std::string>& logs) {
  std::string buf;
  if (world_rank() == 0) {
    const std::uint64_t n = todo.size();
    buf.append(reinterpret_cast<const char*>(&n), sizeof n);
    for (std::size_t t = 0; t < todo.size(); ++t) {
      const std::uint64_t k = todo[t];
      buf.append(reinterpret_cast<const char*>(&k), sizeof k);
      append_sized(buf, logs[t]);
    }
  }
  std::uint64_t bytes = buf.size();
  MPI_Bcast(&bytes, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  std::vector<char> data(buf.begin(), buf.end());
  data.resize(bytes);
  MPI_Bcast(data.data(), static_cast<int>(bytes), MPI_CHAR, 0, MPI_COMM_WORLD);
  if (world_rank() == 0) return;
  std::size_t at = 0;
  std::uint64_t n = 0;
  std::memcpy(&n, data.data() + at, sizeof n), at += sizeof n;
  todo.resize(n), logs.resize(n);
  for (std::size_t t = 0; t < n; ++t) {
    std::uint64_t k = 0;
    std::memcpy(&k, data.data() + at, sizeof k), at += sizeof k;
    todo[t] = k;
    logs[t] = read_sized(data, at);
  }
}

// Rank 0: hands out the indices to whichever rank asks (its own thread
// included) and collects the results. The MPI calls stay on this thread
// (MPI_THREAD_FUNNELED); it polls for messages, sleeping between polls.
std::vector<TaskResult> dispatch(Share& share, const std::function<std::string(std::size_t)>& task,
                                 const FarmOptions& options) {
  const std::size_t count = share.todo.size();
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
    share.done(static_cast<std::size_t>(id), r);  // kept first (a file each; outside the lock)
    std::lock_guard guard(mutex);
    results[static_cast<std::size_t>(id)] = std::move(r);
    ++done;
    if (results[static_cast<std::size_t>(id)].status == TaskResult::Status::NotRun) stopping = true;
  };
  // Rank 0's own share, on a thread with the rank's OpenMP threads (unless
  // the tasks call MPI themselves: then the other ranks compute them all).
  std::exception_ptr local_error;
  bool local_finished = !options.root_computes;
  const int threads = omp_get_max_threads();
  std::thread local;
  if (options.root_computes)
    local = std::thread([&] {
      omp_set_num_threads(threads);
      try {
        for (long long id = take(); id >= 0; id = take())
          store(id, run_one(static_cast<std::size_t>(id), task, share.logs[static_cast<std::size_t>(id)]));
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
  if (local.joinable()) local.join();
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
    std::vector<std::string> descriptions(count), logs(count);
    for (std::size_t t = 0; t < count; ++t) descriptions[t] = read_sized(buffer, at), logs[t] = read_sized(buffer, at);
    worker([&](std::size_t t) { return kind(descriptions[t]); }, logs);
  }
#endif
}

std::string described_identity(const std::string& kind, const std::string& description) {
  return kind + '\n' + description;
}

FarmOutcome farm_described(const std::string& name, const std::vector<std::string>& descriptions,
                           const FarmOptions& options_in) {
  const TaskKind kind = find_task_kind(name);
  FarmOptions options = options_in;
  if (!options.identity)  // what determines a described task's result: its kind and description
    options.identity = [&](std::size_t k) { return described_identity(name, descriptions[k]); };
  Share share = share_of(descriptions.size(), options);
  const auto task = [&](std::size_t k) { return kind(descriptions[k]); };
  if (!ServedRun::active()) return finish(share, run_in_order(share, task, options), options);
#ifdef WEARSCALE_MPI
  const auto start = clock::now();
  std::string message;
  append_sized(message, name);
  const std::uint64_t count = share.todo.size();
  message.append(reinterpret_cast<const char*>(&count), sizeof count);
  for (std::size_t t = 0; t < share.todo.size(); ++t)
    append_sized(message, descriptions[share.todo[t]]), append_sized(message, share.logs[t]);
  for (int r = 1; r < world_size(); ++r)
    MPI_Send(message.data(), static_cast<int>(message.size()), MPI_CHAR, r, kTagEnsemble, MPI_COMM_WORLD);
  auto slots = dispatch(share, [&](std::size_t t) { return task(share.todo[t]); }, options);
  log::info("{}: {} tasks on {} ranks in {:.2f} s", options.label, share.todo.size(), world_size(),
            std::chrono::duration<double>(clock::now() - start).count());
  return finish(share, std::move(slots), options);
#else
  return {};
#endif
}

FarmOutcome farm(std::size_t count, const std::function<std::string(std::size_t)>& task, const FarmOptions& options) {
  if (size() == 1 || !built_with_mpi()) {  // one rank, or alone
    Share share = share_of(count, options);
    return finish(share, run_in_order(share, task, options), options);
  }
#ifdef WEARSCALE_MPI
  const auto start = clock::now();
  FarmOutcome out;
  Share share;
  if (world_rank() == 0) {
    share = share_of(count, options);
    if (share.store != nullptr && share.store->mode() != TaskStore::Mode::Keep)
      throw std::logic_error("task farm: shards and merges run without mpirun");  // the runner refuses them before
  }
  broadcast_slots(share.todo, share.logs);
  const auto slot_task = [&](std::size_t t) { return task(share.todo[t]); };
  if (world_rank() == 0) {
    auto slots = dispatch(share, slot_task, options);
    log::info("{}: {} tasks on {} ranks in {:.2f} s", options.label, share.todo.size(), world_size(),
              std::chrono::duration<double>(clock::now() - start).count());
    out = finish(share, std::move(slots), options);
  } else {
    worker(slot_task, share.logs);
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
