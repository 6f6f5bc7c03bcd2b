// The task farm (core/task_farm.hpp) under mpirun, run by ctest (label "mpi";
// also without mpirun: one rank, the serial path):
//   farm_probe tasks COUNT   COUNT tasks of 1 to 10 ms: every result comes back
//                            to rank 0 in task order with the text its task
//                            made; tasks 3 and 5 (if there) fail, by a
//                            NumericalError and an InputError, marked as such,
//                            the others done; every rank learns the failed
//                            count; a task sees one rank (mpi::Alone), and a
//                            farm inside it runs there; with
//                            more tasks than ranks several ranks take part.
//   farm_probe overhead COUNT [MS] [DIR]   COUNT tasks sleeping MS ms: the farm's cost per task;
//                                          with DIR, each task kept in a task store there (its cost too).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <set>
#include <string>
#include <thread>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/core/task_farm.hpp"
#include "wearscale/core/task_store.hpp"

namespace mpi = wearscale::mpi;

namespace {
int check(bool ok, const std::string& what) {
  if (!ok) std::fprintf(stderr, "rank %d: %s\n", mpi::world_rank(), what.c_str());
  return ok ? 0 : 1;
}

std::string expected_text(std::size_t k) { return "task " + std::to_string(k) + " squared " + std::to_string(k * k); }
}  // namespace

int main(int argc, char** argv) {
  mpi::Session session(argc, argv);
  const std::string mode = argc > 2 ? argv[1] : "";
  const std::size_t count = argc > 2 ? static_cast<std::size_t>(std::atol(argv[2])) : 0;
  if (mode == "tasks") {
    const int ranks = mpi::size();
    int failures = 0;
    const auto outcome = mpi::farm(count, [&](std::size_t k) {
      // A task computes alone, whatever the job's size.
      if (mpi::size() != 1 || mpi::rank() != 0 || mpi::active()) throw std::logic_error("a task sees several ranks");
      // A farm inside a task runs on this rank, in order, and gives every result.
      const auto inner = mpi::farm(3, [](std::size_t j) { return std::to_string(j); });
      if (inner.results.size() != 3 || inner.results[2].text != "2" || inner.results[2].rank != mpi::world_rank())
        throw std::logic_error("a farm inside a task did not run on its rank");
      // Costs differ 10×: 1 ms to 10 ms.
      std::this_thread::sleep_for(std::chrono::milliseconds(1 + static_cast<int>((k * 7) % 10)));
      if (k == 3) throw wearscale::NumericalError("probe", 17, "x", "diverged on purpose");
      if (k == 5) throw wearscale::InputError("probe: key 'x' = 5: refused on purpose");
      return expected_text(k);
    });
    const long long should_fail = (count > 3 ? 1 : 0) + (count > 5 ? 1 : 0);
    failures += check(outcome.failed == should_fail, "failed count on this rank: " + std::to_string(outcome.failed));
    failures += check(outcome.not_run == 0, "tasks not run");
    failures += check(mpi::size() == ranks, "the farm left the rank view changed");
    if (mpi::is_root()) {
      failures += check(outcome.results.size() == count, "one result per task");
      std::set<int> ranks_used;
      for (std::size_t k = 0; k < outcome.results.size(); ++k) {
        const auto& r = outcome.results[k];
        ranks_used.insert(r.rank);
        failures += check(r.rank >= 0 && r.rank < ranks, "task " + std::to_string(k) + ": rank " + std::to_string(r.rank));
        failures += check(r.seconds >= 0.001, "task " + std::to_string(k) + " took no time");
        if (k == 3) {
          failures += check(r.status == mpi::TaskResult::Status::Failed && r.numerical &&
                                r.text.find("diverged on purpose") != std::string::npos,
                            "task 3 is not marked as a numerical failure: " + r.text);
        } else if (k == 5) {
          failures += check(r.status == mpi::TaskResult::Status::Failed && !r.numerical &&
                                r.text.find("refused on purpose") != std::string::npos,
                            "task 5 is not marked as refused: " + r.text);
        } else {
          failures += check(r.status == mpi::TaskResult::Status::Done && r.text == expected_text(k),
                            "task " + std::to_string(k) + ": '" + r.text + "'");
        }
      }
      if (ranks > 1 && count >= 4 * static_cast<std::size_t>(ranks))
        failures += check(ranks_used.size() > 1, "one rank ran every task");
      std::printf("%zu tasks on %d ranks (%zu took part): %s\n", count, ranks, ranks_used.size(),
                  failures == 0 ? "ok" : "FAILED");
    }
    return failures == 0 ? 0 : 1;
  }
  if (mode == "overhead") {
    // Each task sleeps MS ms (argument 3, default 0): over P ranks the ideal wall time is COUNT·MS/P.
    const int ms = argc > 3 ? std::atoi(argv[3]) : 0;
    std::optional<mpi::TaskStore> store;
    mpi::FarmOptions options;
    if (argc > 4 && mpi::is_root()) {
      store.emplace(argv[4]);
      options.identity = [](std::size_t k) { return "probe task " + std::to_string(k); };
    }
    const auto start = std::chrono::steady_clock::now();
    const auto outcome = mpi::farm(count, [ms](std::size_t k) {
      if (ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(ms));
      return std::to_string(k);
    }, options);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (mpi::is_root()) {
      const double ideal = 1e-3 * ms * static_cast<double>(count) / mpi::size();
      std::printf("%zu tasks of %d ms on %d ranks: %.4f s (ideal %.4f s), overhead %.3f ms per task\n", count, ms,
                  mpi::size(), s, ideal, 1e3 * (s - ideal) * mpi::size() / static_cast<double>(count));
    }
    return outcome.failed == 0 ? 0 : 1;
  }
  std::fprintf(stderr, "usage: farm_probe tasks COUNT | overhead COUNT [MS [DIR]]\n");
  return 2;
}
