#include "wearscale/coupling/shear_farm.hpp"

#include <map>
#include <memory>
#include <mutex>
#include <sstream>

#include <fmt/format.h>

#include "wearscale/core/interrupt.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/core/task_farm.hpp"
#include "wearscale/core/task_store.hpp"

namespace wearscale::coupling {

namespace {

constexpr const char* kShearRunTask = "molecular/lammps run";

std::mutex g_studies_mutex;
std::map<std::string, md::ShearTestSpec>& served_studies() {
  static std::map<std::string, md::ShearTestSpec> studies;
  return studies;
}

// One run of a registered study, here: the `call`-th map call's run `index`
// ("material\ncall\nindex"); every other map call gathers nothing, so the
// study stops once that run is done (its cache entry holds what it did).
std::string run_served_shear_run(const std::string& description) {
  std::istringstream in(description);
  std::string material;
  std::size_t call = 0, index = 0;
  if (!std::getline(in, material) || !(in >> call >> index))
    throw std::logic_error("molecular/lammps: a served run's description is garbled: " + description);
  md::ShearTestSpec spec;
  {
    std::lock_guard guard(g_studies_mutex);
    const auto it = served_studies().find(material);
    if (it == served_studies().end()) throw std::logic_error("molecular/lammps: no study of " + material + " on this rank");
    spec = it->second;
  }
  std::string text;
  std::size_t calls = 0;
  const md::RunMap one = [&](std::size_t count, const std::function<std::string(std::size_t)>& task)
      -> std::optional<std::vector<std::string>> {
    if (calls++ == call) {
      if (index >= count) throw std::logic_error("molecular/lammps: a served run beyond its study's runs");
      text = task(index);
    }
    return std::nullopt;
  };
  md::run_shear_study(spec, one);
  return text;
}

}  // namespace

void register_served_shear_study(const std::string& material, const md::ShearTestSpec& spec) {
  {
    std::lock_guard guard(g_studies_mutex);
    served_studies()[material] = spec;
  }
  mpi::register_task_kind(kShearRunTask, run_served_shear_run);
}

md::RunMap served_shear_runs(const std::string& material, std::string label) {
  auto calls = std::make_shared<std::size_t>(0);
  return [material, label = std::move(label), calls](std::size_t count,
                                                     const std::function<std::string(std::size_t)>&)
             -> std::optional<std::vector<std::string>> {
    const std::size_t call = (*calls)++;
    std::vector<std::string> descriptions;
    for (std::size_t k = 0; k < count; ++k) descriptions.push_back(fmt::format("{}\n{}\n{}", material, call, k));
    mpi::FarmOptions options;
    options.label = label;
    options.stop = [] { return interrupt_requested(); };
    const mpi::FarmOutcome outcome = mpi::farm_described(kShearRunTask, descriptions, options);
    std::vector<std::string> out;
    for (std::size_t k = 0; k < count; ++k) {
      const auto& r = outcome.results[k];
      if (r.status == mpi::TaskResult::Status::NotRun)
        throw Interrupted(fmt::format("{}: interrupted, {} of {} runs not started", label, outcome.not_run, count));
      if (r.status == mpi::TaskResult::Status::Failed) {
        if (r.numerical) throw NumericalError("LAMMPS", -1, fmt::format("{}, run {} (rank {})", label, k + 1, r.rank), r.text);
        throw InputError(fmt::format("{}, run {} (rank {}): {}", label, k + 1, r.rank, r.text));
      }
      out.push_back(r.text);
    }
    return out;
  };
}

md::RunMap farmed_shear_runs(std::string label) {
  auto calls = std::make_shared<std::size_t>(0);
  return [label = std::move(label), calls](std::size_t count, const std::function<std::string(std::size_t)>& task)
             -> std::optional<std::vector<std::string>> {
    const std::size_t call = (*calls)++;
    const mpi::TaskStore* store = mpi::TaskStore::current();
    const bool sharded = store != nullptr && store->mode() != mpi::TaskStore::Mode::Keep;
    if (mpi::size() == 1 && !sharded) {  // serial, or alone: the errors as they come
      std::vector<std::string> out;
      for (std::size_t k = 0; k < count; ++k) out.push_back(task(k));
      return out;
    }
    mpi::FarmOptions options;
    options.label = label;
    options.stop = [] { return interrupt_requested(); };
    // Within one case (the run's task store is the case's), a run is its map call and index.
    options.identity = [&](std::size_t k) { return fmt::format("{}\ncall {} run {}", label, call, k); };
    options.name = [&](std::size_t k) { return fmt::format("run {} of call {}", k + 1, call + 1); };
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
