#pragma once
// What a run finds in its output folder before it writes: the runs of others
// (refused), the checkpoint or summary of a run to continue (--resume), the
// checkpoint or kept tasks of an unfinished run (refused without --resume),
// and, when a signal stops it, how to go on. Private to the runner.
#include <filesystem>
#include <string>
#include <vector>

#include "wearscale/core/errors.hpp"
#include "runner_plan.hpp"

namespace wearscale::studies::runner {

/// The one rule of what a run may remove: only what the previous run of its folder wrote (its summary.json lists
/// its files and, for a sweep, its runs' folders; OutputSet::commit removes those it does not write again). Runs
/// in the folder that no summary accounts for (left by a sweep that never completed, or put there by hand) would
/// stay mixed with this run's: OutputError before any work, nothing changed. `own`: the run's own run folders;
/// `sweep_runs_only`: only folders holding a log.txt count (the runs of an ensemble).
void refuse_foreign_runs(const std::filesystem::path& dir, const std::vector<std::filesystem::path>& own,
                         bool sweep_runs_only);

/// What --resume finds in a run's folder: a checkpoint to continue from, the
/// summary of a run that had completed, or nothing yet (it starts afresh).
void find_resume_point(PreparedRun& run);

/// A fresh run never throws away the checkpoint of an unfinished one.
void check_fresh_start(const PreparedRun& run);

/// --resume of a sweep: the folder holds no summary yet, or a sweep's (never a completed single run's, whose
/// outputs the sweep's summary would replace).
void require_sweep_summary_or_none(const std::filesystem::path& dir);

/// The kept tasks in a run's folder, for this case: tasks kept for other
/// parameters (a resume with another case) are not taken; they go.
void claim_task_store(const PreparedRun& run);

/// How to continue an interrupted run, added to the Interrupted message.
[[noreturn]] void rethrow_interrupted(const Interrupted& e, const std::string& command,
                                      const std::filesystem::path& dir);

}  // namespace wearscale::studies::runner
