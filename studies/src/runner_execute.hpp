#pragma once
// One run of a prepared case: into its folder on this process, or under
// `mpirun -np P` with every rank in it (a distributed study). Private to the
// runner.
#include <string>

#include "runner_plan.hpp"

namespace wearscale::studies::runner {

/// Runs a prepared case into its folder: every output staged and published
/// together with summary.json (OutputSet), the checkpoint removed after that.
/// `command` locks the folder when the caller has not (the runs of a sweep),
/// and gives the run its own log.txt.
void execute(PreparedRun& run, const RunOptions& options, bool show_progress, const std::string* command);

/// A single run without mpirun: its folder locked and checked (no foreign
/// runs; a checkpoint to resume, or none left by an unfinished run), then run.
RunSummary run_single(PreparedRun& run, const RunOptions& options, int threads);

/// Under `mpirun -np P` (P > 1): one run of a distributed study, every rank in
/// it. Every check (the case, the study's keys, rank 0's output folder) is
/// agreed by all ranks before any work (mpi::refuse_together: a refusal ends
/// every rank with status 2, nothing written); then rank 0 runs the study into
/// its folder as a single run does and the other ranks make the same
/// collective calls (Study::run_other_rank), writing nothing.
RunSummary run_distributed(const CaseLoader& parse, const RunOptions& options);

}  // namespace wearscale::studies::runner
