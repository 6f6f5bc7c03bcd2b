#pragma once
// The one runner of every study (studies/study.hpp): runs a case file or the
// keys a command's flags set, checks the case, runs its study, writes run.h5
// (version, provenance, headline results) and summary.json (same name and
// shape for every study) into the output folder.
// A [sweep] runs the case once per value of one key (in parallel when cores
// allow) and gathers the headline figures in one table; [sweep.series] (a
// second key and its values) repeats the sweep once per series value, one
// table and one curve each.
//
// Ensembles scale out. Under `mpirun -np P` (or srun) the runs of a
// sweep go over the ranks by the task farm (core/task_farm.hpp): dynamic
// scheduling, rank 0 alone writes the sweep's table and summary, each run
// writes its own folder; the results are those of a run without mpirun. A
// run that fails with bad input or a numerical failure is marked in the table
// (column `failed`, summary.json `failed`) and the job ends with status 1
// once the table is written. `task = "K/N"` (`--task K/N`, a job array) runs
// only the runs k with k mod N = K−1 into the same folder (a shared folder
// lock, no shared file written; each shard leaves task-K-of-N.json);
// merge_shards() then writes the table and summary a whole run would have.
//
// Long runs checkpoint ([run] checkpoint_interval, checkpoint_steps) into
// checkpoint.h5 in their output folder; `resume_dir` continues a killed or
// interrupted run from it (a sweep: only its unfinished runs), with results
// identical to an uninterrupted run. The checkpoint is removed when the run
// completes.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "wearscale/io/config.hpp"

namespace wearscale::studies {

/// The most runs one [sweep] may hold (its values times its series values):
/// every run is checked and held before the first starts.
inline constexpr std::size_t max_sweep_runs = 10000;

struct RunOptions {
  std::filesystem::path case_file;                ///< empty: no case file (a command's flags give the keys)
  /// The case as TOML text instead of a file (Python's dict or string case): case_file then only
  /// names it in messages, and its relative file names are relative to the working directory.
  std::optional<std::string> case_text;
  std::string study;                              ///< the study to run; empty: the case says (study_of)
  std::string command;                            ///< the command line for messages; empty: `wearscale run ...`
  /// "KEY=VALUE" from a command's alias flags, each with the flag as typed ("--hurst 1.5"), which a
  /// message about its key names; applied before `overrides`.
  std::vector<std::pair<std::string, std::string>> flags;
  std::vector<std::string> overrides;             ///< "KEY=VALUE" from --set (messages name "--set KEY=VALUE")
  std::optional<std::filesystem::path> output_dir;  ///< --out, else [output].dir
  std::optional<std::filesystem::path> resume_dir;  ///< --resume: the output folder of the run to continue
  /// --task K/N: only the K-th of N shards of the case's ensemble (its [sweep]); none: all (an empty text
  /// is refused, as an empty --out or --resume is).
  std::optional<std::string> task;
};

struct RunSummary {
  std::string study;                ///< the study's name
  std::string case_name;
  std::filesystem::path output_dir;
  std::vector<std::string> scales;  ///< the parts it ran, in order (a pipeline's scale ids)
  nlohmann::json provenance;        ///< wearscale version, time, command
  nlohmann::json results;           ///< headline figures {name: {value, unit, description}}
  nlohmann::json notes = nlohmann::json::object();  ///< the study's other summary fields (RunContext::note)
  nlohmann::json parameters;        ///< the resolved case
  std::vector<std::filesystem::path> files;
  bool complete_before = false;  ///< resumed, but it had completed: its files were not written again
  // A sweep: the key, and one summary per value (results above stay empty).
  std::string sweep_key;
  std::vector<std::string> sweep_values;  ///< per run
  std::string series_key;                 ///< [sweep.series] key, if any
  std::vector<std::string> series_values; ///< per run, when there is a series
  std::vector<RunSummary> runs;
  nlohmann::json to_json() const;
};

/// Throws InputError for a bad case (before any output is written; for a
/// sweep, before any of its runs starts), OutputError when the output folder
/// is in use by another process, holds the checkpoint of an unfinished run
/// (without resume_dir), or cannot be written, NumericalError when a solver
/// fails, and Interrupted on SIGINT/SIGTERM (after saving the checkpoints).
/// The outputs of a run appear together, with its summary.json last
/// (OutputSet); a sweep shares the thread budget (-j) among its runs.
RunSummary run_case(const RunOptions& options);

/// `wearscale merge DIR`: the sweep table and summary.json of the ensemble
/// whose shards (`--task K/N`) ran into DIR, the same files a run of the whole
/// ensemble writes. InputError, nothing written, when a run is not complete
/// (naming the missing runs and the shards that owe them), when DIR holds no
/// shards, or when the case changed since; OutputError while a shard still runs.
RunSummary merge_shards(const std::filesystem::path& dir, const std::string& command);

/// Parses the case afresh (a sweep applies each value to its own copy).
using CaseLoader = std::function<Config()>;
/// The case of `options` as run_case reads it: its text, its file, or none (a command's keys).
CaseLoader case_loader(const RunOptions& options);

/// Everything run_case checks before it writes anything, without running or
/// writing: the case from `parse` with `options.overrides`, its sweep (key,
/// values, table) and the scales of every run. Returns each run's output
/// folder; throws what run_case would for the same input (InputError).
std::vector<std::filesystem::path> check_case(const CaseLoader& parse, const RunOptions& options);

/// What `wearscale check` says of a case, which it reads as run_case does,
/// every key and every independent error at once, and neither runs nor writes
/// (a study that reads its keys at the start of its run is taken up to its
/// check of the whole case, with a scratch folder for what it opens then).
struct CaseReport {
  std::string study, case_name, case_file;
  std::vector<std::string> scales;
  std::vector<std::filesystem::path> output_dirs;  ///< one per run (each run of a sweep)
  std::string sweep_key;                           ///< a sweep: its key and each run's value
  std::vector<std::string> sweep_values;
  nlohmann::json parameters;  ///< the resolved case with every default the run applies (a sweep: its first run's)
  nlohmann::json defaults;    ///< those defaults alone: {dotted key: value}
  /// Keys of the study's schema still absent: {key: its default in words, e.g. "0.6 d_c"}, worked out at run time.
  nlohmann::json described_defaults;
  /// Per run: the needs it declared before it starts (require_memory: each a whole data set's, checked
  /// against the memory limit), each "what" with its bytes.
  std::vector<std::vector<std::pair<std::string, double>>> memory;
  nlohmann::json to_json() const;
  /// The report as `wearscale check` prints it: the resolved case as TOML, defaults marked, then the memory.
  std::string text() const;
};

CaseReport inspect_case(const CaseLoader& parse, const RunOptions& options);

}  // namespace wearscale::studies
