#pragma once
// Independent tasks shared out over a few threads: the runs of a sweep, the
// junction runs of nano/dem. Each worker takes the next task in turn, so long
// and short tasks balance; the calling thread is one of the workers.
#include <omp.h>

#include <atomic>
#include <cstddef>
#include <functional>
#include <thread>
#include <vector>

namespace wearscale {

struct WorkerOptions {
  unsigned workers = 1;          ///< threads, the calling one included
  int omp_threads = 0;           ///< OpenMP threads of each spawned worker (0: as the caller's)
  bool caller_omp_too = false;   ///< the calling thread also takes omp_threads
  std::function<bool()> stop;    ///< no task starts once it returns true (e.g. on SIGINT)
};

/// Runs task(k) for every k in [0, count); a task handles its own exceptions.
inline void run_on_workers(std::size_t count, const WorkerOptions& options, const std::function<void(std::size_t)>& task) {
  std::atomic<std::size_t> next{0};
  auto work = [&](bool spawned) {
    if (options.omp_threads > 0 && (spawned || options.caller_omp_too)) omp_set_num_threads(options.omp_threads);
    for (std::size_t k = next++; k < count && !(options.stop && options.stop()); k = next++) task(k);
  };
  std::vector<std::thread> pool;
  for (unsigned w = 1; w < options.workers; ++w) pool.emplace_back(work, true);
  work(false);
  for (auto& t : pool) t.join();
}

}  // namespace wearscale
