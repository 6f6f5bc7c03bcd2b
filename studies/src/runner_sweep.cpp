#include "runner_sweep.hpp"

#include <algorithm>
#include <chrono>
#include <exception>
#include <mutex>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/costliest_first.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/fft.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/core/output_lock.hpp"
#include "wearscale/core/progress.hpp"
#include "wearscale/core/task_farm.hpp"
#include "wearscale/core/worker_pool.hpp"
#include "runner_execute.hpp"
#include "runner_output_folder.hpp"
#include "runner_publish.hpp"

namespace wearscale::studies::runner {

namespace {

// How the runs of a sweep went: per run, why it failed ("" if it ran), and
// which rank ran it, on how many threads, for how long.
struct SweepOutcome {
  std::vector<std::string> failures;
  nlohmann::json tasks = nlohmann::json::array();
  bool output_failed = false;  // a farmed run failed to write its outputs: status 2

  void add_task(std::size_t k, int rank, int threads, double seconds) {
    tasks.push_back({{"run", k + 1}, {"rank", rank}, {"threads", threads}, {"seconds", seconds}});
  }
};

// A run's summary as it travels from the rank that ran it to rank 0.
nlohmann::json run_message(const RunSummary& s) {
  std::vector<std::string> files;
  for (const auto& f : s.files) files.push_back(f.string());
  return {{"results", s.results}, {"notes", s.notes}, {"files", files}, {"complete_before", s.complete_before}};
}

void take_run_message(RunSummary& s, const nlohmann::json& j) {
  s.results = j.at("results");
  s.notes = j.at("notes");
  s.files.clear();
  for (const auto& f : j.at("files")) s.files.emplace_back(f.get<std::string>());
  s.complete_before = j.at("complete_before").get<bool>();
}

// The sweep's folder, on rank 0: locked (shared among the shards of one
// ensemble), checked for runs not its own, and each of `mine` found ready:
// its point to resume from, or no unfinished run's checkpoint. A shard
// leaves its manifest. Resuming, every checkpoint is read (and its FFT plans
// imported) before any run makes a plan.
OutputLock claim_sweep_folder(SweepPlan& plan, const std::vector<std::size_t>& mine, const RunOptions& options,
                              const std::optional<Shard>& shard, const std::string& command,
                              const std::string& ensemble) {
  const RunSummary& sweep = plan.sweep;
  std::vector<PreparedRun>& runs = plan.runs;
  OutputLock lock = shard ? OutputLock::folder(sweep.output_dir, command, OutputLock::Mode::Shared, ensemble)
                          : OutputLock::folder(sweep.output_dir, command);
  if (options.resume_dir) require_sweep_summary_or_none(sweep.output_dir);
  refuse_foreign_runs(sweep.output_dir, run_folders_of(plan), false);
  // The unfinished files of a sweep killed while it wrote its table or plots (its runs clean their own).
  remove_stale_partials(sweep.output_dir);
  if (options.resume_dir) {
    for (const auto k : mine) find_resume_point(runs[k]);
    const auto finished = std::count_if(mine.begin(), mine.end(), [&](std::size_t k) { return runs[k].complete; });
    log::info("resuming the sweep in {}: {} of {} runs complete", sweep.output_dir.string(), finished, mine.size());
  } else {
    for (const auto k : mine) check_fresh_start(runs[k]);
  }
  if (shard) {
    std::vector<std::size_t> owned;
    for (const auto k : mine) owned.push_back(k + 1);
    write_manifest(sweep.output_dir, *shard, ensemble, sweep.study, options, command, {{"runs", owned}});
  }
  return lock;
}

// Under mpirun: the runs over the ranks by the task farm, a failed run
// marked in `outcome`. Returns whether this rank goes on to publish (rank 0);
// the others end here, with mpi::TasksFailed when a run failed.
bool run_on_ranks(SweepPlan& plan, const std::vector<std::size_t>& mine, const RunOptions& options,
                  const std::string& command, const std::string& what, SweepOutcome& outcome) {
  std::vector<PreparedRun>& runs = plan.runs;
  log::info("{} over {}: {} runs on {} MPI ranks × {} thread(s) → {}", what, plan.sweep.sweep_key, mine.size(),
            mpi::size(), thread_budget(), plan.sweep.output_dir.string());
  mpi::FarmOptions farm_options;
  farm_options.label = what;
  farm_options.stop = [] { return interrupt_requested(); };
  farm_options.root_computes =
      std::none_of(runs.begin(), runs.end(), [](const PreparedRun& r) { return r.study->calls_mpi(); });
  const auto farmed = mpi::farm(
      mine.size(),
      [&](std::size_t t) {
        PreparedRun& run = runs[mine[t]];
        if (options.resume_dir && !run.checkpoints) find_resume_point(run);  // rank 0 found them all before
        execute(run, options, false, &command);
        return run_message(run.summary).dump();
      },
      farm_options);
  if (farmed.not_run > 0) {  // stopped by a signal: checkpoints saved, resume continues
    const Interrupted e(fmt::format("{} stopped by a signal: {} of {} runs not finished", what, farmed.not_run,
                                    mine.size()));
    rethrow_interrupted(e, command, plan.sweep.output_dir);
  }
  // A run that could not write its outputs (a full disk) ends the job with status 2 on every rank, as a
  // serial run's would; rank 0 alone knows the failures, and tells.
  bool output_failed = false;
  if (mpi::is_root())
    for (const auto& r : farmed.results) output_failed = output_failed || r.output;
  output_failed = mpi::sum(output_failed ? 1LL : 0LL) > 0;
  if (!mpi::is_root()) {
    if (farmed.failed > 0) throw mpi::TasksFailed("", false, output_failed);
    return false;
  }
  outcome.output_failed = output_failed;
  for (std::size_t t = 0; t < mine.size(); ++t) {
    const auto& r = farmed.results[t];
    outcome.add_task(mine[t], r.rank, r.threads, r.seconds);
    if (r.status == mpi::TaskResult::Status::Done)
      take_run_message(runs[mine[t]].summary, nlohmann::json::parse(r.text));
    else
      outcome.failures[mine[t]] = fmt::format("{} (rank {})", r.text, r.rank);
  }
  return true;
}

// Without mpirun: the runs side by side on threads, the -j budget shared out
// (runs side by side, the rest inside each run); the first failure ends the
// sweep, as a single run's does.
void run_on_threads(SweepPlan& plan, const std::vector<std::size_t>& mine, const RunOptions& options, int threads,
                    const std::string& command, const std::string& what, SweepOutcome& outcome) {
  std::vector<PreparedRun>& runs = plan.runs;
  const unsigned budget = static_cast<unsigned>(threads);
  const unsigned workers = plan.parallel ? std::min<unsigned>(budget, static_cast<unsigned>(std::max<std::size_t>(1, mine.size()))) : 1u;
  const int per_run = static_cast<int>(std::max(1u, budget / workers));
  if (workers > 1) FFTPlanCache::global().set_threads(per_run);
  log::info("{} over {}: {} runs on {} worker(s) × {} thread(s) → {}", what, plan.sweep.sweep_key, mine.size(), workers,
            per_run, plan.sweep.output_dir.string());
  std::vector<std::exception_ptr> errors(mine.size());
  std::size_t done = 0;
  std::mutex progress_mutex;
  Progress progress(what, static_cast<double>(mine.size()), "runs");
  WorkerOptions pool;
  pool.workers = workers;
  pool.omp_threads = workers > 1 ? per_run : 0;
  pool.caller_omp_too = true;
  pool.stop = [] { return interrupt_requested(); };
  std::vector<double> seconds(mine.size(), 0.0);
  // With several workers the costliest runs start first (the rest fill in at
  // the end); one worker runs them in the order given (nothing to balance).
  std::vector<double> costs;
  for (const auto k : mine) costs.push_back(workers > 1 ? runs[k].study->estimated_cost() : 0.0);
  const auto order = costliest_first(costs);
  run_on_workers(mine.size(), pool, [&](std::size_t slot) {
    const std::size_t t = order[slot];
    const auto start = std::chrono::steady_clock::now();
    try {
      execute(runs[mine[t]], options, false, &command);
    } catch (...) {
      errors[t] = std::current_exception();
    }
    seconds[t] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::lock_guard guard(progress_mutex);
    progress.update(static_cast<double>(++done));
  });
  for (std::size_t t = 0; t < mine.size(); ++t)
    outcome.add_task(mine[t], 0, workers > 1 ? per_run : static_cast<int>(budget), seconds[t]);
  progress.finish();
  try {
    throw_if_interrupted("sweep");  // also when the signal came between runs
    for (auto& e : errors)
      if (e) std::rethrow_exception(e);
  } catch (const Interrupted& e) {
    rethrow_interrupted(e, command, plan.sweep.output_dir);
  }
}

// The failed runs among `which`, for the message that ends the job: "run K (KEY=VALUE): why".
std::vector<std::string> failed_runs(const SweepPlan& plan, const std::vector<std::size_t>& which,
                                     const std::vector<std::string>& failures) {
  std::vector<std::string> failed;
  for (const auto k : which)
    if (!failures[k].empty())
      failed.push_back(fmt::format("run {} ({}={}): {}", k + 1, plan.sweep.sweep_key, plan.sweep.sweep_values[k],
                                   failures[k]));
  return failed;
}

// A shard's part of the sweep: its own runs only; `wearscale merge` writes the tables once every shard is done.
RunSummary shard_part(const SweepPlan& plan, const std::vector<std::size_t>& mine, const Shard& shard,
                      const SweepOutcome& outcome, const std::string& what, const std::string& command) {
  const RunSummary& sweep = plan.sweep;
  RunSummary part = sweep;
  part.sweep_values.clear();
  part.series_values.clear();
  part.files = {sweep.output_dir / manifest_name(shard)};
  for (const auto k : mine) {
    part.runs.push_back(plan.runs[k].summary);
    part.sweep_values.push_back(sweep.sweep_values[k]);
    if (!plan.series_key.empty()) part.series_values.push_back(sweep.series_values[k]);
  }
  const std::vector<std::string> failed = failed_runs(plan, mine, outcome.failures);
  if (!failed.empty())
    throw mpi::TasksFailed(fmt::format("{}: {} of its {} runs failed: {}; rerun them with: {} --resume {}", what,
                                       failed.size(), mine.size(), fmt::join(failed, "; "), command,
                                       sweep.output_dir.string()),
                           true, outcome.output_failed);
  log::info("shard {} done; once every shard is: wearscale merge {}", shard.text(), sweep.output_dir.string());
  return part;
}

}  // namespace

RunSummary run_sweep(const CaseLoader& parse, const RunOptions& options, Config& probe, int threads,
                     const std::optional<Shard>& shard) {
  std::optional<SweepPlan> planned;
  mpi::refuse_together([&] {
    const mpi::Alone alone;  // each run of a sweep runs on one rank (a task of the farm): so is it prepared
    planned = plan_sweep(parse, options, probe);
    describe_sweep(*planned, options);
  });
  SweepPlan& plan = *planned;
  std::vector<std::size_t> mine;  // the runs this job runs
  for (std::size_t k = 0; k < plan.runs.size(); ++k)
    if (!shard || shard->owns(k)) mine.push_back(k);
  const std::string command = command_line(options, threads);
  const std::string ensemble = ensemble_id(plan);
  std::optional<OutputLock> lock;
  mpi::refuse_together([&] {  // the folder and what is in it: rank 0's
    if (mpi::is_root()) lock.emplace(claim_sweep_folder(plan, mine, options, shard, command, ensemble));
  });
  FFTPlanCache::global().set_rigor(plan.runs.front().fft_rigor);
  SweepOutcome outcome;
  outcome.failures.resize(plan.runs.size());
  const std::string what = shard ? fmt::format("shard {} of the sweep", shard->text()) : std::string("sweep");
  if (mpi::size() > 1) {
    if (!run_on_ranks(plan, mine, options, command, what, outcome)) return plan.sweep;
  } else {
    run_on_threads(plan, mine, options, threads, command, what, outcome);
  }
  if (shard) return shard_part(plan, mine, *shard, outcome, what, command);
  publish_sweep(plan, probe, outcome.failures, outcome.tasks);
  const std::vector<std::string> failed = failed_runs(plan, mine, outcome.failures);
  if (!failed.empty())
    throw mpi::TasksFailed(fmt::format("{}: {} of {} runs failed, marked in the table (failed = 1): {}; rerun them "
                                       "with: {} --resume {}",
                                       what, failed.size(), plan.runs.size(), fmt::join(failed, "; "), command,
                                       plan.sweep.output_dir.string()),
                           true, outcome.output_failed);
  return plan.sweep;
}

}  // namespace wearscale::studies::runner
