#pragma once
// What a finished sweep publishes in its folder: one table per series value
// (the swept value, then every headline figure of its runs), the study's
// sweep plots and summary.json, all appearing together (OutputSet). Private
// to the runner.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runner_sweep_plan.hpp"

namespace wearscale::studies::runner {

/// The sweep tables, the study's sweep plots and summary.json of `plan`.
/// `failures` (one per run, "" if it ran) marks the runs that failed: a
/// column `failed` and the list in summary.json; no plots then.
/// `tasks`: which rank ran each run, on how many threads, for how long (null: not known, as when merged).
void publish_sweep(SweepPlan& plan, Config& probe, const std::vector<std::string>& failures,
                   const nlohmann::json& tasks = nullptr);

}  // namespace wearscale::studies::runner
