#pragma once
// The runs of a [sweep], or of one shard of it: on threads within the -j
// budget, or under mpirun over the ranks by the task farm; then the sweep's
// tables and summary (a shard writes only its manifest). Private to the
// runner.
#include <optional>

#include "runner_shard.hpp"

namespace wearscale::studies::runner {

/// Plans the sweep of `probe` (the case with its --set options), checks and
/// locks its folder, and runs its runs (those of `shard` only, when given).
/// Without mpirun they run side by side on threads within the `threads`
/// budget, and the first failure ends the sweep, as a single run's does.
/// Under mpirun they go over the ranks by the task farm, and a run that fails
/// is marked in the table (column `failed`); the job then ends with
/// mpi::TasksFailed once the table is written.
RunSummary run_sweep(const CaseLoader& parse, const RunOptions& options, Config& probe, int threads,
                     const std::optional<Shard>& shard);

}  // namespace wearscale::studies::runner
