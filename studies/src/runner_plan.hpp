#pragma once
// A run planned: its case read (the case file or text, the command's alias
// flags, every --set), its study chosen, every key checked and its output
// folder named, before anything is written. Private to the runner.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "wearscale/core/fft.hpp"
#include "wearscale/core/task_store.hpp"
#include "wearscale/io/checkpoint.hpp"
#include "wearscale/io/config.hpp"
#include "wearscale/studies/runner.hpp"
#include "wearscale/studies/study.hpp"

namespace wearscale::studies::runner {

/// A case checked and ready to run: every key read, every scale built.
struct PreparedRun {
  Config cfg;
  std::unique_ptr<Study> study;
  RunSummary summary;
  CheckpointPolicy policy;
  PlanRigor fft_rigor = PlanRigor::Measure;
  std::string fingerprint;                 ///< the parameters that determine the results
  std::optional<Checkpointer> checkpoints;
  bool resume = false;                     ///< continues from its checkpoint
  bool complete = false;                   ///< resumed, but it had finished: its outputs stand
  /// Its ensembles' tasks (tasks/): kept and taken (Keep), one shard's share (Shard), or all taken (Assemble: merge).
  mpi::TaskStore::Mode tasks = mpi::TaskStore::Mode::Keep;
  std::size_t shard = 1, shards = 1;
  std::function<std::string(std::size_t)> owner;  ///< Assemble: who owes a missing task
  std::vector<std::pair<std::string, double>> memory;  ///< what its checks declared it needs (require_memory)
};

/// The case (parsed afresh by `parse`) with its alias flags, its --set
/// overrides, then the `extra` ones (a sweep value, where it comes from).
/// A message about a key names what set it last: "--hurst 1.5", "--set KEY=VALUE".
Config load(const CaseLoader& parse, const RunOptions& options,
            const std::vector<std::pair<std::string, std::string>>& extra = {});

/// The threads this process may use (-j, else OMP_NUM_THREADS, else the cores).
int thread_budget();

/// The command that runs (or continues) this case with the same options and
/// threads, for messages: a resumed run is bit for bit only on as many threads.
std::string command_line(const RunOptions& options, int threads);

/// The study a case runs: the one its command names, else the one it names.
std::unique_ptr<Study> study_for(const Config& cfg, const RunOptions& options);

/// Paths from the command line end up in summary.json, which holds UTF-8 only;
/// --out and --resume name folders.
void require_utf8_paths(const RunOptions& options);

/// The provenance of a run in summary.json: what made it, the same for the same
/// inputs (a resumed run's summary is the uninterrupted one's, byte for byte).
/// run.h5 adds when and by which command line.
nlohmann::json provenance_of(const RunSummary& summary, const RunOptions& options);

/// The case checked, every independent error found at once
/// (Config::collect_errors), into `out` (none: the case's [output] dir). A
/// study that reads its keys at the start of run() goes on collecting there,
/// until it has checked the whole case.
PreparedRun prepare(Config cfg_in, const std::optional<std::filesystem::path>& out, const RunOptions& options);

/// The folder of a run's kept tasks (made when the first is kept).
inline std::filesystem::path tasks_dir(const PreparedRun& run) { return run.summary.output_dir / "tasks"; }

}  // namespace wearscale::studies::runner
