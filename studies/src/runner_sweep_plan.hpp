#pragma once
// A [sweep] planned: the case once per value of one key (and once more per
// value of its [sweep.series] key), every run checked and held before the
// first starts, each into its own folder of the sweep's. Private to the runner.
#include <filesystem>
#include <string>
#include <vector>

#include "runner_plan.hpp"

namespace wearscale::studies::runner {

/// A sweep checked and ready: every run prepared, nothing written yet.
struct SweepPlan {
  RunSummary sweep;
  std::vector<std::string> values;      ///< the swept key's values
  std::vector<std::string> labels;      ///< their run folders' names
  std::string series_key;               ///< [sweep.series] key, or ""
  std::vector<std::string> series;      ///< its values
  std::vector<std::string> run_series;  ///< the series value of each run
  std::string table_name;
  bool parallel = true;
  std::vector<PreparedRun> runs;
};

/// The name of a run's folder: the swept key's last part and its value,
/// "thickness=1e-6", with any other character of a file name made '_'.
std::string label_of(const std::string& key, const std::string& value);

/// Reads and checks [sweep] of `probe` (the case with its --set options) and
/// prepares every run (InputError, nothing written, for a bad one).
SweepPlan plan_sweep(const CaseLoader& parse, const RunOptions& options, Config& probe);

/// What the sweep's summary says of the whole: its parts, provenance and parameters.
void describe_sweep(SweepPlan& plan, const RunOptions& options);

/// The run folders of a sweep, relative to its folder (a series' runs one level further down).
std::vector<std::filesystem::path> run_folders_of(const SweepPlan& plan);

}  // namespace wearscale::studies::runner
