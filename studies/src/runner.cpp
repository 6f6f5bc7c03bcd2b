// The runner's entry points: a case run (a single run, a distributed one
// under mpirun, one shard of its ensembles, or a [sweep]), checked without
// running (`wearscale check`), or its folders named. Each phase has its file:
//   runner_plan            a case read and checked, nothing written
//   runner_sweep_plan      a [sweep]'s runs, each planned
//   runner_output_folder   what a run finds in its folder: others' runs, a point to resume
//   runner_execute         one run, on this process or over the MPI ranks
//   runner_sweep           a sweep's runs on threads or over the ranks
//   runner_shard           one shard of an ensemble (--task K/N)
//   runner_merge           the shards' outputs made one (`wearscale merge`)
//   runner_publish         a sweep's tables and summary.json
#include "wearscale/studies/runner.hpp"

#include <optional>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/io/checkpoint.hpp"
#include "case_report.hpp"
#include "runner_execute.hpp"
#include "runner_plan.hpp"
#include "runner_shard.hpp"
#include "runner_sweep.hpp"
#include "runner_sweep_plan.hpp"

namespace wearscale::studies {

using namespace runner;

CaseLoader case_loader(const RunOptions& options) {
  return [options] {
    if (options.case_text) return Config::from_string(*options.case_text, options.case_file.string());
    return options.case_file.empty() ? Config::from_string("", "<command line>") : Config::load(options.case_file);
  };
}

RunSummary run_case(const RunOptions& options_in) {
  RunOptions options = options_in;
  const int threads = thread_budget();
  const CaseLoader parse = case_loader(options);
  // Under mpirun every rank reads the case; a refusal is every rank's (status 2, said once).
  std::optional<Config> probe;
  std::optional<Shard> shard;
  mpi::refuse_together([&] {
    require_utf8_paths(options_in);
    shard = parse_shard(options.task);
    probe = load(parse, options);
    const bool sweep = probe->has("sweep");
    if (shard && !sweep && mpi::size() > 1)
      throw InputError(fmt::format("--task {}: the shards of one run's ensembles run without mpirun (as the tasks of "
                                   "a job array); under mpirun the whole ensemble spreads over the {} ranks: drop "
                                   "--task, or run each shard as its own process",
                                   shard->text(), mpi::size()));
    if (options.resume_dir)
      options.output_dir = resume_folder(*options.resume_dir, options.output_dir.value_or(std::filesystem::path()));
  });
  if (probe->has("sweep")) return run_sweep(parse, options, *probe, threads, shard);
  if (mpi::size() > 1) return run_distributed(parse, options);
  PreparedRun run = prepare(std::move(*probe), options.output_dir, options);  // a single run: the file is parsed once
  if (shard) return run_shard(run, options, *shard);
  return run_single(run, options, threads);
}

std::vector<std::filesystem::path> check_case(const CaseLoader& parse, const RunOptions& options) {
  require_utf8_paths(options);
  Config probe = load(parse, options);
  std::vector<std::filesystem::path> folders;
  if (probe.has("sweep")) {
    for (const auto& r : plan_sweep(parse, options, probe).runs) folders.push_back(r.summary.output_dir);
  } else {
    folders.push_back(prepare(std::move(probe), options.output_dir, options).summary.output_dir);
  }
  return folders;
}

CaseReport inspect_case(const CaseLoader& parse, const RunOptions& options) {
  require_utf8_paths(options);
  Config probe = load(parse, options);
  std::vector<PreparedRun> runs;
  CaseReport report;
  if (probe.has("sweep")) {
    SweepPlan plan = plan_sweep(parse, options, probe);
    report.sweep_key = plan.sweep.sweep_key;
    report.sweep_values = plan.sweep.sweep_values;
    runs = std::move(plan.runs);
  } else {
    runs.push_back(prepare(std::move(probe), options.output_dir, options));
  }
  for (auto& run : runs) {
    if (!run.cfg.fully_checked()) {  // a study that reads its keys in run(): up to its check
      const MemoryTally tally;
      check_keys_in_run(*run.study, run.cfg);
      run.memory.insert(run.memory.end(), tally.requests().begin(), tally.requests().end());
    }
    report.output_dirs.push_back(run.summary.output_dir);
    report.memory.push_back(run.memory);
  }
  const PreparedRun& first = runs.front();
  report.study = first.summary.study;
  report.case_name = first.summary.case_name;
  report.case_file = options.case_file.string();
  report.scales = first.summary.scales;
  describe_defaults(report, *first.study, first.cfg);
  return report;
}

}  // namespace wearscale::studies
