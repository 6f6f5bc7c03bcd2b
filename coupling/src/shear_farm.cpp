#include "wearscale/coupling/shear_farm.hpp"

#include <fmt/format.h>

#include "wearscale/core/interrupt.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/core/task_farm.hpp"

namespace wearscale::coupling {

md::RunMap farmed_shear_runs(std::string label) {
  return [label = std::move(label)](std::size_t count, const std::function<std::string(std::size_t)>& task)
             -> std::optional<std::vector<std::string>> {
    if (mpi::size() == 1) {  // serial, or alone: the errors as they come
      std::vector<std::string> out;
      for (std::size_t k = 0; k < count; ++k) out.push_back(task(k));
      return out;
    }
    mpi::FarmOptions options;
    options.label = label;
    options.stop = [] { return interrupt_requested(); };
    const mpi::FarmOutcome outcome = mpi::farm(count, task, options);
    if (outcome.not_run > 0) throw Interrupted(fmt::format("{}: interrupted, {} of {} runs not started", label,
                                                           outcome.not_run, count));
    if (outcome.failed > 0) {
      if (!mpi::is_root()) throw mpi::TasksFailed("", false);
      std::string why;
      for (std::size_t k = 0; k < outcome.results.size(); ++k)
        if (outcome.results[k].status == mpi::TaskResult::Status::Failed)
          why += fmt::format("\n  run {} (rank {}): {}", k + 1, outcome.results[k].rank, outcome.results[k].text);
      throw mpi::TasksFailed(fmt::format("{}: {} of {} LAMMPS runs failed:{}", label, outcome.failed, count, why), true);
    }
    if (!mpi::is_root()) return std::nullopt;
    std::vector<std::string> out;
    for (const auto& r : outcome.results) out.push_back(r.text);
    return out;
  };
}

}  // namespace wearscale::coupling
