#include "runner_execute.hpp"

#include <omp.h>

#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/core/output_lock.hpp"
#include "wearscale/core/output_set.hpp"
#include "wearscale/core/utc_time.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "result_bounds.hpp"
#include "runner_output_folder.hpp"

namespace wearscale::studies::runner {

void execute(PreparedRun& run, const RunOptions& options, bool show_progress, const std::string* command) {
  RunSummary& summary = run.summary;
  summary.provenance = provenance_of(summary, options);
  if (run.complete) {
    log::info("{}: already complete", summary.output_dir.string());
    return;
  }
  std::optional<OutputLock> lock;
  if (command != nullptr) lock.emplace(OutputLock::folder(summary.output_dir, *command));
  create_output_folder(summary.output_dir);
  // A run of an ensemble (a sweep's) keeps its own log beside its outputs, on whichever rank runs it.
  std::optional<log::TaskLog> task_log;
  if (command != nullptr) {
    task_log.emplace(summary.output_dir / "log.txt");
    log::task_note(fmt::format("case '{}': {} → {} ({}, rank {} of {}, {} thread(s), {})", summary.case_name,
                               fmt::join(summary.scales, " → "), summary.output_dir.string(),
                               run.resume ? "resumed" : "started", mpi::world_rank(), mpi::world_size(),
                               omp_get_max_threads(), utc_now()));
  }
  // Temporary files left by a killed run; a resumed one may continue some (a DEM study's snapshot file),
  // so they go only once it has completed.
  if (!run.resume) remove_stale_partials(summary.output_dir);
  if (!run.checkpoints) run.checkpoints.emplace(summary.output_dir / "checkpoint.h5", run.fingerprint, run.policy);
  OutputSet outputs(summary.output_dir, "summary.json");
  H5Writer h5(summary.output_dir / "run.h5");
  h5.set_attribute("/", "case_file", options.case_file.string());
  h5.set_attribute("/", "case_toml", run.cfg.to_toml());
  h5.set_attribute("/", "command", command_line(options, thread_budget()));

  h5.set_attribute("/", "study", summary.study);

  RunContext context(summary.output_dir, h5, show_progress, &*run.checkpoints);
  if (run.tasks != mpi::TaskStore::Mode::Assemble) claim_task_store(run);
  mpi::TaskStore task_store(tasks_dir(run), run.tasks, run.shard, run.shards, run.fingerprint);
  task_store.owner = run.owner;
  try {
    run.study->run(run.cfg, context);
  } catch (const InputError& e) {  // a key of a study that reads them in run(), after others in error
    if (run.cfg.has_collected_errors() && dynamic_cast<const OutputError*>(&e) == nullptr)
      throw run.cfg.collected_with(e.what());
    throw;
  }
  run.cfg.raise_collected_errors();  // a study that read keys without checking the whole case: before any output
  // A shard writes none of the run's outputs, even when the other shards' tasks were all there: merge does.
  if (run.tasks == mpi::TaskStore::Mode::Shard) throw mpi::ShardDone("every task of the run is done");
  for (const auto& [name, r] : context.results().items()) {
    const double value = r["value"].get<double>();
    // Never a NaN (null in JSON), infinite or unphysical headline figure: the bounds a resumed or merged
    // result is held to as well (result_bounds.hpp).
    if (const std::string why = result_outside_bounds(name, value, r["unit"].get<std::string>()); !why.empty())
      throw NumericalError("case " + summary.case_name, 0, name, "a result outside physical bounds: " + why);
    h5.write_scalar("/results/" + name, value, r["unit"].get<std::string>());
    h5.set_attribute("/results/" + name, "description", r["description"].get<std::string>());
  }
  context.draw_figures();  // all of the run's, with one gnuplot
  summary.results = context.results();
  summary.notes = context.notes();
  summary.files = context.files();
  h5.commit();
  summary.files.insert(summary.files.begin(), h5.final_path());
  summary.files.push_back(summary.output_dir / "summary.json");
  outputs.commit(summary.to_json());
  for (const auto& [name, r] : summary.results.items())
    log::task_note(fmt::format("{} = {} {}", name, r["value"].get<double>(), r["unit"].get<std::string>()));
  log::task_note(fmt::format("case '{}': complete ({})", summary.case_name, utc_now()));
  if (run.checkpoints->saves() > 0)
    log::debug("{}: {} checkpoints written in {:.3f} s", summary.output_dir.string(), run.checkpoints->saves(),
               run.checkpoints->seconds_saving());
  run.checkpoints->discard();  // complete: nothing to resume
  task_store.discard();
  if (run.resume) remove_stale_partials(summary.output_dir);  // those this run did not continue
}

RunSummary run_single(PreparedRun& run, const RunOptions& options, int threads) {
  const std::string command = command_line(options, threads);
  const OutputLock lock = OutputLock::folder(run.summary.output_dir, command);
  refuse_foreign_runs(run.summary.output_dir, {}, true);
  if (options.resume_dir)
    find_resume_point(run);
  else
    check_fresh_start(run);
  FFTPlanCache::global().set_rigor(run.fft_rigor);
  log::info("case '{}': {} → {}", run.summary.case_name, fmt::join(run.summary.scales, " → "),
            run.summary.output_dir.string());
  try {
    execute(run, options, true, nullptr);
  } catch (const Interrupted& e) {
    rethrow_interrupted(e, command, run.summary.output_dir);
  }
  return run.summary;
}

RunSummary run_distributed(const CaseLoader& parse, const RunOptions& options) {
  std::optional<PreparedRun> run;
  std::optional<OutputLock> lock;
  const std::string command = command_line(options, thread_budget());
  mpi::refuse_together([&] {
    require_utf8_paths(options);
    // The case as a single run reads it: the file, the command's flags (--n, --grid, ...) and every --set.
    Config cfg = load(parse, options);
    run.emplace(prepare(std::move(cfg), options.output_dir, options));
    if (!run->study->distributed())
      throw InputError(fmt::format("study '{}' runs on one rank only ({} ranks started; under mpirun the contact "
                                   "study is distributed, a rough wear map's surfaces, the junction runs of a "
                                   "nano/dem scale, the strength table's points, a DEM study with [dem] engine = "
                                   "\"lammps\", and the runs of any [sweep]); run it without mpirun",
                                   run->summary.study, mpi::size()));
  });
  mpi::refuse_together([&] {  // the folder: rank 0's alone
    if (!mpi::is_root()) return;
    lock.emplace(OutputLock::folder(run->summary.output_dir, command));
    if (!options.resume_dir) return check_fresh_start(*run);
    // Resumed: the tasks its ensembles had finished are taken (tasks/); a checkpoint is a single run's,
    // or one of a study whose state rank 0 gathers (a DEM study on the LAMMPS engine).
    const auto checkpoint = run->summary.output_dir / "checkpoint.h5";
    if (std::error_code ec; std::filesystem::exists(checkpoint, ec) && !run->study->resumes_distributed())
      throw InputError(fmt::format("--resume {}: {} is the checkpoint of a run made without mpirun; resume it "
                                   "without mpirun",
                                   options.resume_dir->string(), checkpoint.string()));
    find_resume_point(*run);
  });
  // A resumed run that had completed: nothing to do, on any rank.
  if (mpi::sum(mpi::is_root() && run->complete ? 1LL : 0LL) > 0) {
    if (mpi::is_root()) log::info("{}: already complete", run->summary.output_dir.string());
    return run->summary;
  }
  FFTPlanCache::global().set_rigor(run->fft_rigor);
  if (!mpi::is_root()) {
    run->study->run_other_rank(run->cfg);
    return run->summary;
  }
  log::info("case '{}': study {} on {} MPI ranks → {}", run->summary.case_name, run->summary.study, mpi::size(),
            run->summary.output_dir.string());
  execute(*run, options, true, nullptr);
  return run->summary;
}

}  // namespace wearscale::studies::runner
