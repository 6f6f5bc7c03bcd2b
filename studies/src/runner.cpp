#include "wearscale/studies/runner.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <charconv>
#include <atomic>
#include <exception>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/costliest_first.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/fft.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/core/output_lock.hpp"
#include "wearscale/core/output_set.hpp"
#include "wearscale/core/progress.hpp"
#include "wearscale/core/sha256.hpp"
#include "wearscale/core/task_farm.hpp"
#include "wearscale/core/task_store.hpp"
#include "wearscale/core/text_file.hpp"
#include "wearscale/core/units.hpp"
#include "wearscale/core/utc_time.hpp"
#include "wearscale/core/utf8.hpp"
#include "wearscale/core/worker_pool.hpp"
#include "wearscale/io/checkpoint.hpp"
#include "wearscale/io/config.hpp"
#include "wearscale/io/csv.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/studies/study.hpp"
#include "case_report.hpp"
#include "result_bounds.hpp"

namespace wearscale::studies {

nlohmann::json RunSummary::to_json() const {
  std::vector<std::string> names;
  for (const auto& f : files) names.push_back(f.string());
  nlohmann::json j = {{"study", study},         {"case", case_name},     {"output_dir", output_dir.string()},
                      {"scales", scales},       {"files", names},        {"parameters", parameters},
                      {"provenance", provenance}};
  if (sweep_key.empty()) {
    j["results"] = results;
    for (const auto& [key, value] : notes.items())
      if (!j.contains(key)) j[key] = value;
  } else {
    nlohmann::json runs_json = nlohmann::json::array();
    for (std::size_t k = 0; k < runs.size(); ++k) {
      runs_json.push_back({{"value", sweep_values[k]}, {"output_dir", runs[k].output_dir.string()},
                           {"results", runs[k].results}});
      if (!series_key.empty()) runs_json.back()["series"] = series_values[k];
    }
    j["sweep"] = {{"key", sweep_key}, {"values", sweep_values}, {"runs", runs_json}};
    if (!series_key.empty()) j["sweep"]["series"] = {{"key", series_key}, {"values", series_values}};
  }
  return j;
}

namespace {

// The case (parsed afresh by `parse`) with its alias flags, its --set
// overrides, then the `extra` ones (a sweep value, where it comes from).
// A message about a key names what set it last: "--hurst 1.5", "--set KEY=VALUE".
Config load(const CaseLoader& parse, const RunOptions& options,
            const std::vector<std::pair<std::string, std::string>>& extra = {}) {
  Config cfg = parse();
  for (const auto& [assignment, flag] : options.flags) cfg.override_value(assignment, flag);
  for (const auto& o : options.overrides) cfg.override_value(o, is_utf8(o) ? "--set " + o : std::string("--set"));
  for (const auto& [value, origin] : extra) cfg.override_value(value, origin);
  return cfg;
}

// The threads this process may use (-j, else OMP_NUM_THREADS, else the cores).
int thread_budget() { return std::max(1, omp_get_max_threads()); }

// The command that runs (or continues) this case with the same options and
// threads, for messages: a resumed run is bit for bit only on as many threads.
std::string command_line(const RunOptions& options, int threads) {
  if (!options.command.empty())  // a command's own line, with its threads
    return options.command.find(" -j") != std::string::npos || options.command.find("--threads") != std::string::npos
               ? options.command
               : options.command + fmt::format(" -j {}", threads);
  std::string line = "wearscale run " + options.case_file.string();
  for (const auto& o : options.overrides) line += fmt::format(" --set '{}'", o);
  return line + fmt::format(" -j {}", threads);
}

// A case checked and ready to run: every key read, every scale built.
struct PreparedRun {
  Config cfg;
  std::unique_ptr<Study> study;
  RunSummary summary;
  CheckpointPolicy policy;
  PlanRigor fft_rigor = PlanRigor::Measure;
  std::string fingerprint;                 // the parameters that determine the results
  std::optional<Checkpointer> checkpoints;
  bool resume = false;                     // continues from its checkpoint
  bool complete = false;                   // resumed, but it had finished: its outputs stand
  // Its ensembles' tasks (tasks/): kept and taken (Keep), one shard's share (Shard), or all taken (Assemble: merge).
  mpi::TaskStore::Mode tasks = mpi::TaskStore::Mode::Keep;
  std::size_t shard = 1, shards = 1;
  std::function<std::string(std::size_t)> owner;  // Assemble: who owes a missing task
  std::vector<std::pair<std::string, double>> memory;  // what its checks declared it needs (require_memory)
};

// The folder of a run's kept tasks (made when the first is kept).
std::filesystem::path tasks_dir(const PreparedRun& run) { return run.summary.output_dir / "tasks"; }

// The kept tasks in a run's folder, for this case: tasks kept for other
// parameters (a resume with another case) are not taken; they go.
void claim_task_store(const PreparedRun& run) {
  std::error_code ec;
  if (!std::filesystem::exists(tasks_dir(run), ec)) return;
  if (!std::filesystem::is_directory(tasks_dir(run), ec))
    throw OutputError(fmt::format("{} is not a folder; a run keeps its finished tasks there: move it away, or write "
                                  "to another folder",
                                  tasks_dir(run).string()));
  const std::string was = mpi::TaskStore::case_of(tasks_dir(run));
  if (was == run.fingerprint) return;
  if (mpi::TaskStore::holds_tasks(tasks_dir(run)))
    log::warn("{}: its kept tasks belong to other parameters; they are run again", tasks_dir(run).string());
  std::filesystem::remove_all(tasks_dir(run), ec);
}

// The study a case runs: the one its command names, else the one it names.
std::unique_ptr<Study> study_for(const Config& cfg, const RunOptions& options) {
  cfg.mark_used("case.study");
  return study_registry().create(options.study.empty() ? study_of(cfg) : options.study);
}

// A folder given on the command line: a name (not empty, which would be taken as no --out at all) of a
// folder, not "-" (wearscale writes files into a folder, never to stdout).
void require_folder_name(const std::filesystem::path& dir, const char* option) {
  if (dir.empty())
    throw InputError(fmt::format("{} '': an empty folder name; allowed: the name of a folder to write into (without "
                                 "{}: the case's [output] dir)",
                                 option, option));
  if (dir == "-")
    throw InputError(fmt::format("{} -: wearscale writes a folder of files, not to standard output; allowed: the name "
                                 "of a folder (--json prints the results on standard output)",
                                 option));
}

// Paths from the command line end up in summary.json, which holds UTF-8 only.
void require_utf8_paths(const RunOptions& options) {
  require_utf8_path(options.case_file, "case file");
  if (options.output_dir) require_folder_name(*options.output_dir, "--out");
  if (options.resume_dir) require_folder_name(*options.resume_dir, "--resume");
  if (options.output_dir) require_utf8_path(*options.output_dir, "--out");
  if (options.resume_dir) require_utf8_path(*options.resume_dir, "--resume");
}

// The provenance of a run in summary.json: what made it, the same for the same
// inputs (a resumed run's summary is the uninterrupted one's, byte for byte).
// run.h5 adds when and by which command line.
nlohmann::json provenance_of(const RunSummary& summary, const RunOptions& options) {
  return {{"wearscale_version", WEARSCALE_VERSION}, {"study", summary.study}, {"case_file", options.case_file.string()}};
}

// An output folder given as an existing file is bad input (exit 2), found before anything is written.
void require_folder_or_nothing(const std::filesystem::path& dir, const char* option) {
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
    throw InputError(fmt::format("{} = '{}' cannot be used as an output folder (not a folder); allowed: a folder that "
                                 "can be created and written",
                                 option, dir.string()));
}

PreparedRun prepare_keys(Config cfg_in, const std::optional<std::filesystem::path>& out, const RunOptions& options) {
  PreparedRun run{std::move(cfg_in), {}, {}, {}, PlanRigor::Measure, {}, std::nullopt, false, false,
                  mpi::TaskStore::Mode::Keep, 1, 1, {}, {}};
  Config& cfg = run.cfg;
  run.study = study_for(cfg, options);
  run.summary.study = run.study->name();
  const std::string default_name = run.study->default_case_name();  // empty: the case must name itself
  run.summary.case_name = default_name.empty() ? cfg.string("case.name") : cfg.string_or("case.name", default_name);
  cfg.string_or("case.description", "");
  const std::string default_dir = run.study->default_output_dir();
  const std::string case_dir = cfg.string_or("output.dir", default_dir.empty() ? "out/" + run.summary.case_name : default_dir);
  run.summary.output_dir = out ? *out : std::filesystem::path(case_dir);
  require_folder_or_nothing(run.summary.output_dir, out ? "--out" : "output.dir");
  cfg.mark_used("sweep");  // read by run_case
  // [run]: how the run is carried out, not what it computes.
  run.policy = checkpoint_policy(cfg);
  const Config r = cfg.section("run");
  run.fft_rigor = r.choice_or("fft_planning", "measure", {"measure", "estimate"}) == "estimate" ? PlanRigor::Estimate
                                                                                                : PlanRigor::Measure;
  study_registry().read_run_limits(cfg);  // every study's limits (contact: gather_limit), on every run
  run.summary.scales = run.study->prepare(cfg);
  run.summary.parameters = cfg.to_json();
  run.fingerprint = case_fingerprint(run.summary.parameters);
  return run;
}

// A case checked as prepare_keys() reads it, every independent error found
// at once (Config::collect_errors). A study that reads its keys at the start
// of run() goes on collecting there, until it has checked the whole case.
PreparedRun prepare(Config cfg_in, const std::optional<std::filesystem::path>& out, const RunOptions& options) {
  const Config cfg = cfg_in;  // shares the case's state: its errors
  cfg.collect_errors(true);
  const MemoryTally tally;
  PreparedRun run = [&] {
    try {
      return prepare_keys(std::move(cfg_in), out, options);
    } catch (const OutputError&) {
      throw;
    } catch (const InputError& e) {
      if (cfg.has_collected_errors()) throw cfg.collected_with(e.what());
      throw;
    } catch (const std::exception&) {  // a consequence of a value in error standing in: the errors are the news
      if (cfg.has_collected_errors()) cfg.raise_collected_errors();
      throw;
    }
  }();
  cfg.raise_collected_errors();
  cfg.collect_errors(!cfg.fully_checked());
  run.memory = tally.requests();
  return run;
}

// A completed run's summary.json is a sweep's (it has "sweep") or a single run's: --resume continues one
// of the same kind only (a sweep resumed over a single run's folder would replace its outputs).
void require_summary_of_kind(const std::filesystem::path& summary_file, const nlohmann::json& j, bool sweep) {
  const bool is_sweep = j.is_object() && j.contains("sweep");
  if (is_sweep == sweep) return;
  throw InputError(fmt::format("--resume: {} is the summary of a completed {}, and the case is {}; resume it with the "
                               "case it was run with, or write to another folder (nothing was changed)",
                               summary_file.string(), is_sweep ? "sweep" : "single run (no [sweep])",
                               sweep ? "a sweep" : "a single run"));
}

// Subfolders of `dir` (one or two levels down) that hold a run: its summary.json, checkpoint.h5 or log.txt
// (with `sweep_runs_only`, log.txt alone: the runs of an ensemble).
std::vector<std::filesystem::path> run_folders_in(const std::filesystem::path& dir, bool sweep_runs_only) {
  std::vector<std::filesystem::path> found;
  const auto holds_run = [&](const std::filesystem::path& d) {
    std::error_code ec;
    if (std::filesystem::exists(d / "log.txt", ec)) return true;
    return !sweep_runs_only &&
           (std::filesystem::exists(d / "summary.json", ec) || std::filesystem::exists(d / "checkpoint.h5", ec));
  };
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (!it->is_directory(ec) || it->path().filename().string().starts_with(".")) continue;
    const auto name = it->path().filename();
    if (name == "tasks" || name == "logs") continue;  // a run's own kept tasks and task logs
    if (holds_run(it->path())) {
      found.push_back(name);
      continue;
    }
    std::error_code inner;
    for (std::filesystem::directory_iterator jt(it->path(), inner), jend; !inner && jt != jend; jt.increment(inner))
      if (jt->is_directory(inner) && holds_run(jt->path())) found.push_back(name / jt->path().filename());
  }
  std::sort(found.begin(), found.end());
  return found;
}

// The one rule of what a run may remove: only what the previous run of its folder wrote (its summary.json lists
// its files and, for a sweep, its runs' folders; OutputSet::commit removes those it does not write again). Runs
// in the folder that no summary accounts for (left by a sweep that never completed, or put there by hand) would
// stay mixed with this run's: refused before any work, nothing changed.
void refuse_foreign_runs(const std::filesystem::path& dir, const std::vector<std::filesystem::path>& own,
                         bool sweep_runs_only) {
  nlohmann::json previous = nlohmann::json::object();
  std::error_code ec;
  if (std::filesystem::is_regular_file(dir / "summary.json", ec)) try {
      previous = nlohmann::json::parse(read_text_file(dir / "summary.json", "summary", std::uintmax_t{1} << 26));
    } catch (const std::exception&) {
    }
  const auto owned = OutputSet::owned_folders(previous);
  std::vector<std::string> foreign;
  for (const auto& f : run_folders_in(dir, sweep_runs_only)) {
    const auto in = [&](const std::vector<std::filesystem::path>& set) {
      return std::any_of(set.begin(), set.end(), [&](const auto& o) { return o == f || *f.begin() == o; });
    };
    if (!in(own) && !in(owned)) foreign.push_back((dir / f).string());
  }
  if (foreign.empty()) return;
  const std::size_t shown = std::min<std::size_t>(foreign.size(), 3);
  throw OutputError(fmt::format(
      "{} holds {} run folder(s) that are not this run's and that no completed run of the folder lists ({}{}): a "
      "run would leave them mixed with its own; --resume them with the case that made them, move or delete them, or "
      "write to another folder (nothing was changed)",
      dir.string(), foreign.size(), fmt::join(foreign.begin(), foreign.begin() + static_cast<long>(shown), ", "),
      foreign.size() > shown ? ", ..." : ""));
}

// What --resume finds in a run's folder: a checkpoint to continue from, the
// summary of a run that had completed, or nothing yet (it starts afresh).
void find_resume_point(PreparedRun& run) {
  const auto dir = run.summary.output_dir;
  run.checkpoints.emplace(dir / "checkpoint.h5", run.fingerprint, run.policy);
  std::error_code ec;
  if (std::filesystem::exists(dir / "checkpoint.h5", ec)) {
    run.checkpoints->load();
    run.resume = true;
    return;
  }
  const auto summary_file = dir / "summary.json";
  if (!std::filesystem::exists(summary_file, ec)) {
    log::info("{}: no checkpoint yet: the run starts from the beginning", dir.string());
    return;
  }
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(read_text_file(summary_file, "summary", std::uintmax_t{1} << 26));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: not a wearscale summary ({})", summary_file.string(), e.what()));
  }
  if (!j.is_object()) throw InputError(fmt::format("{}: not a wearscale summary", summary_file.string()));
  require_summary_of_kind(summary_file, j, false);
  const std::string was = case_fingerprint(j.value("parameters", nlohmann::json::object()));
  if (was != run.fingerprint) {
    const std::string diff = describe_case_difference(was, run.fingerprint);
    throw InputError(fmt::format("{}: this run completed with other parameters{}; resume with the case file and --set "
                                 "options it was run with, or write to another folder",
                                 summary_file.string(), diff.empty() ? "" : " (" + diff + ")"));
  }
  if (const std::string broken = OutputSet::verify(dir, j); !broken.empty()) {
    log::warn("{}: the outputs of the completed run are not intact ({}): the run starts again", dir.string(), broken);
    return;
  }
  // Its figures as a computed run's are held to: a summary changed by hand (or by another program) is no result.
  if (const std::string why = results_problem(j.value("results", nlohmann::json::object())); !why.empty())
    throw InputError(fmt::format("{}: {}; no run writes that (the summary was changed or damaged): delete {} and run "
                                 "it again",
                                 summary_file.string(), why, dir.string()));
  run.summary.results = j.value("results", nlohmann::json::object());
  for (const auto& [key, value] : j.items())  // the study's own fields
    if (!RunSummary{}.to_json().contains(key) && key != "results") run.summary.notes[key] = value;
  for (const auto& f : j.value("files", nlohmann::json::array()))
    if (f.is_string()) run.summary.files.emplace_back(f.get<std::string>());
  run.complete = true;
  run.summary.complete_before = true;
}

// A fresh run never throws away the checkpoint of an unfinished one.
void check_fresh_start(const PreparedRun& run) {
  require_fresh_start(run.summary.output_dir / "checkpoint.h5");
  if (mpi::TaskStore::holds_tasks(tasks_dir(run)))
    throw OutputError(fmt::format("{} holds the finished tasks of an unfinished run; continue it with --resume {}, or "
                                  "delete {} to start afresh",
                                  run.summary.output_dir.string(), run.summary.output_dir.string(),
                                  tasks_dir(run).string()));
}

// Runs a prepared case into its folder: every output staged and published
// together with summary.json (OutputSet), the checkpoint removed after that.
// `command` locks the folder when the caller has not (the runs of a sweep).
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

// How to continue an interrupted run, added to the Interrupted message.
[[noreturn]] void rethrow_interrupted(const Interrupted& e, const std::string& command,
                                      const std::filesystem::path& dir) {
  std::error_code ec;
  bool kept = false;  // anything but the folder's lock: a checkpoint, kept tasks, finished runs
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
    kept = kept || entry.path().filename() != OutputLock::kFolderLockName;
  if (!kept) throw Interrupted(fmt::format("{}; nothing was written (run it again to start afresh)", e.what()));
  // A resumed run's own line says it already (as `--resume DIR` or `--resume=DIR`).
  const bool resuming = command.find(" --resume") != std::string::npos;
  throw Interrupted(fmt::format("{}; continue with: {}{}", e.what(), command,
                                resuming ? std::string() : " --resume " + dir.string()));
}

std::string label_of(const std::string& key, const std::string& value) {
  std::string leaf = key.substr(key.rfind('.') + 1) + "=" + value;
  for (auto& c : leaf)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '=' || c == '.' || c == '-' || c == '+' || c == '_'))
      c = '_';
  return leaf;
}

// The name of a swept key's column in a sweep table: its last two components
// joined, "materials.layer.thickness" → "layer_thickness" (the table adds
// the unit: "layer_thickness_m").
std::string swept_column(const std::string& key) {
  const auto last = key.rfind('.');
  if (last == std::string::npos || last == 0) return key;
  const auto before = key.rfind('.', last - 1);
  std::string column = key.substr(before == std::string::npos ? 0 : before + 1);
  std::replace(column.begin(), column.end(), '.', '_');
  return column;
}

// The checks of a [sweep] that need no run: the key, its values, the table.
void check_sweep(const Config& probe, const std::string& key, const std::vector<std::string>& values,
                 const std::vector<std::string>& labels, const std::string& table_name) {
  for (const char* reserved : {"output", "sweep"})
    if (key == reserved || key.rfind(std::string(reserved) + ".", 0) == 0)
      throw probe.error("sweep.key", fmt::format("[{}] cannot be swept (each run of a sweep writes into its own "
                                                 "folder of the sweep's output folder)", reserved),
                        "a key of what the case computes, e.g. materials.layer.thickness");
  if (!probe.has(key))
    throw probe.error("sweep.key", "the swept key is not in the case (give it a value there first)", "a key of the case");
  // Two values are one run when they are the same text, give the same folder, or the same quantity ("1 um" and
  // 1e-6): each value looked up among those before it (a sort, not all pairs: a sweep may hold 10 000 values).
  std::map<std::string, std::size_t> seen_text, seen_label;
  std::map<double, std::size_t> seen_number;
  for (std::size_t a = 0; a < values.size(); ++a) {
    std::optional<std::size_t> first;
    const auto look = [&](auto& seen, const auto& key) {
      const auto [it, inserted] = seen.emplace(key, a);
      if (!inserted && (!first || it->second < *first)) first = it->second;
    };
    look(seen_text, values[a]);
    look(seen_label, labels[a]);
    try {
      look(seen_number, units::parse_quantity(values[a]).value);
    } catch (const std::exception&) {
    }
    if (first)
      throw probe.error("sweep.values",
                        fmt::format("values {} ('{}') and {} ('{}') are the same run (folder {})", *first + 1,
                                    values[*first], a + 1, values[a], labels[a]),
                        "distinct values");
  }
  const bool plain = !table_name.empty() && table_name.front() != '.' && table_name.find('/') == std::string::npos &&
                     table_name.find('\0') == std::string::npos;
  if (!plain || is_reserved_output_name(table_name) ||
      std::find(labels.begin(), labels.end(), table_name) != labels.end())
    throw probe.error("sweep.table", "not a file name for the sweep table",
                      "a plain file name in the sweep's folder (no '/', not hidden, not a run's folder nor one of the "
                      "runner's own files: run.h5, summary.json, checkpoint.h5, log.txt, task-K-of-N.json)");
}

// What the runner holds for a prepared run of a sweep besides what its study
// keeps (Study::prepared_bytes): its case, summary and checkpoint policy.
// Measured about 29 KB for the pin-on-disc case (289 MB maximum resident for
// a 10 000-run sweep prepared, bench/results/reliability.md); the estimate
// leaves room for larger cases.
constexpr double prepared_run_bytes = 256.0 * 1024.0;

// A sweep checked and ready: every run prepared, nothing written yet.
struct SweepPlan {
  RunSummary sweep;
  std::vector<std::string> values;      // the swept key's values
  std::vector<std::string> labels;      // their run folders' names
  std::string series_key;               // [sweep.series] key, or ""
  std::vector<std::string> series;      // its values
  std::vector<std::string> run_series;  // the series value of each run
  std::string table_name;
  bool parallel = true;
  std::vector<PreparedRun> runs;
};

SweepPlan plan_sweep(const CaseLoader& parse, const RunOptions& options, Config& probe) {
  SweepPlan plan;
  const std::string key = probe.string("sweep.key");
  const auto values = probe.values_as_text("sweep.values");
  plan.table_name = probe.string_or("sweep.table", "sweep.csv");
  plan.parallel = probe.boolean_or("sweep.parallel", true);
  // [sweep.series]: the sweep once more per value of a second key.
  plan.series_key = probe.has("sweep.series") ? probe.string("sweep.series.key") : std::string();
  plan.series = plan.series_key.empty() ? std::vector<std::string>{""} : probe.values_as_text("sweep.series.values");
  const std::vector<std::string>& series = plan.series;
  // Every run is prepared (and held) before any starts: their number is bounded before the first.
  const double run_count = static_cast<double>(values.size()) * static_cast<double>(series.size());
  if (run_count > static_cast<double>(max_sweep_runs))
    throw probe.error(plan.series_key.empty() ? "sweep.values" : "sweep.series.values",
                      fmt::format("{:.0f} runs ({} values{})", run_count, values.size(),
                                  plan.series_key.empty() ? std::string()
                                                          : fmt::format(" × {} series values", series.size())),
                      fmt::format("at most {} runs in one sweep; split it into several sweeps", max_sweep_runs));
  plan.values = values;
  for (const auto& v : values) plan.labels.push_back(label_of(key, v));
  check_sweep(probe, key, values, plan.labels, plan.table_name);
  if (!plan.series_key.empty() && !probe.has(plan.series_key))
    throw probe.error("sweep.series.key", "the series key is not in the case (give it a value there first)",
                      "a key of the case");
  RunSummary& sweep = plan.sweep;
  {
    const auto study = study_for(probe, options);
    sweep.study = study->name();
    const std::string default_name = study->default_case_name();
    sweep.case_name = default_name.empty() ? probe.string("case.name") : probe.string_or("case.name", default_name);
    const std::string default_dir = study->default_output_dir();
    sweep.output_dir = options.output_dir ? *options.output_dir
                                          : std::filesystem::path(probe.string_or(
                                                "output.dir", default_dir.empty() ? "out/" + sweep.case_name : default_dir));
  }
  sweep.sweep_key = key;
  sweep.series_key = plan.series_key;
  // Every run is checked before any starts. A run's case is the sweep's without its [sweep] (the case that
  // reproduces that run alone; each run holding all the values made the preparation grow as their square).
  const std::string where = probe.where("sweep.values");
  Config base = load(parse, options);
  base.erase("sweep");
  std::vector<std::string> run_value;
  for (const auto& sv : series) {
    const auto folder =
        plan.series_key.empty() ? sweep.output_dir : sweep.output_dir / label_of(plan.series_key, sv);
    for (std::size_t k = 0; k < values.size(); ++k) {
      throw_if_interrupted("preparing the sweep's runs (nothing was written)");
      Config cfg = base.clone();
      cfg.override_value(key + "=" + values[k], fmt::format("{} (sweep.values[{}])", where, k));
      if (!plan.series_key.empty()) cfg.override_value(plan.series_key + "=" + sv, probe.where("sweep.series.values"));
      plan.runs.push_back(prepare(std::move(cfg), folder / plan.labels[k], options));
      if (plan.runs.size() == 1)  // what every run holds until it runs, from the first: within the memory limit
        require_memory(run_count * (prepared_run_bytes + plan.runs.front().study->prepared_bytes()),
                       fmt::format("a sweep of {:.0f} runs (each checked and held before any starts)", run_count),
                       "split it into several sweeps");
      run_value.push_back(values[k]);
      plan.run_series.push_back(sv);
    }
  }
  sweep.sweep_values = run_value;
  if (!plan.series_key.empty()) sweep.series_values = plan.run_series;
  return plan;
}

// The run folders of a sweep, relative to its folder (a series' runs one level further down).
std::vector<std::filesystem::path> run_folders_of(const SweepPlan& plan) {
  std::vector<std::filesystem::path> out;
  for (const auto& r : plan.runs) out.push_back(r.summary.output_dir.lexically_relative(plan.sweep.output_dir));
  return out;
}

// --resume of a sweep: the folder holds no summary yet, or a sweep's (never a completed single run's, whose
// outputs the sweep's summary would replace).
void require_sweep_summary_or_none(const std::filesystem::path& dir) {
  const auto file = dir / "summary.json";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return;
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(read_text_file(file, "summary", std::uintmax_t{1} << 26));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: not a wearscale summary ({})", file.string(), e.what()));
  }
  require_summary_of_kind(file, j, true);
}

// A shard of an ensemble (--task K/N): the runs k with k mod N = K − 1.
struct Shard {
  std::size_t index = 1, of = 1;  // K, N
  std::string text() const { return fmt::format("{}/{}", index, of); }
  bool owns(std::size_t k) const { return k % of == index - 1; }
};

std::optional<Shard> parse_shard(const std::optional<std::string>& given) {
  if (!given) return std::nullopt;
  const std::string& text = *given;
  const auto bad = [&] {
    return InputError(fmt::format("--task '{}': not a shard; allowed: K/N with 1 <= K <= N <= 1000000 (the K-th of N "
                                  "shards of the case's ensemble), e.g. --task 2/8",
                                  is_utf8(text) ? text : std::string("?")));
  };
  const auto slash = text.find('/');
  if (slash == std::string::npos) throw bad();
  const auto number = [&](std::string_view s) {
    std::size_t v = 0;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || ec != std::errc() || ptr != s.data() + s.size() || v < 1 || v > 1000000) throw bad();
    return v;
  };
  const std::string_view all(text);
  Shard shard{number(all.substr(0, slash)), number(all.substr(slash + 1))};
  if (shard.index > shard.of) throw bad();
  return shard;
}

// A run's summary as it travels from the rank that ran it to rank 0, and back from its summary.json.
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

// What the sweep's summary says of the whole: its parts, provenance and parameters.
void describe_sweep(SweepPlan& plan, const RunOptions& options) {
  RunSummary& sweep = plan.sweep;
  sweep.scales = plan.runs.front().summary.scales;
  sweep.provenance = provenance_of(sweep, options);
  sweep.parameters = plan.runs.front().summary.parameters;
  sweep.parameters["sweep"] = {{"key", sweep.sweep_key}, {"values", plan.values}};
  if (!plan.series_key.empty())
    sweep.parameters["sweep"]["series"] = {{"key", plan.series_key}, {"values", plan.series}};
}

// The id shared by the shards of one ensemble: the case that determines the
// results, with its sweep (not [run] or [output]: a resume may change those).
std::string ensemble_id(const SweepPlan& plan) {
  Sha256 h;
  h.field(case_fingerprint(plan.sweep.parameters));
  h.field(plan.sweep.parameters["sweep"].dump());
  h.field(plan.sweep.study);
  return h.hex();
}

std::string manifest_name(const Shard& shard) { return fmt::format("task-{}-of-{}.json", shard.index, shard.of); }

// A shard's manifest in the ensemble's folder: which ensemble, which shard,
// and the case as it ran (the file, its text, the flags), for `merge`.
void write_manifest(const std::filesystem::path& dir, const Shard& shard, const std::string& ensemble,
                    const std::string& study, const RunOptions& options, const std::string& command,
                    const nlohmann::json& extra) {
  nlohmann::json manifest = {
      {"ensemble", ensemble},
      {"task", shard.index},
      {"of", shard.of},
      {"study", study},
      {"case_file", options.case_file.string()},
      {"case_file_absolute",
       options.case_file.empty() ? std::string() : std::filesystem::absolute(options.case_file).string()},
      {"case_text", options.case_text ? *options.case_text
                    : options.case_file.empty()
                        ? std::string()
                        : read_text_file(options.case_file, "case file", std::uintmax_t{1} << 26)},
      {"flags", options.flags},
      {"overrides", options.overrides},
      {"command", command}};
  manifest.update(extra);
  write_file_atomically(dir / manifest_name(shard), manifest.dump(2) + "\n", Commit::Now);
}

// The id shared by the shards of one run's ensembles: its study and the case that determines the results.
std::string ensemble_id(const PreparedRun& run) {
  Sha256 h;
  h.field(run.fingerprint);
  h.field(run.summary.study);
  return h.hex();
}

// Who owes task k of an ensemble, for merge's refusal: under every shard count the manifests show.
std::string owner_of(std::size_t k, const std::vector<nlohmann::json>& manifests) {
  std::vector<std::size_t> counts;
  for (const auto& m : manifests) {
    const auto of = m["of"].get<std::size_t>();
    if (std::find(counts.begin(), counts.end(), of) == counts.end()) counts.push_back(of);
  }
  std::vector<std::string> owed;
  for (const auto of : counts) {
    const Shard s{k % of + 1, of};
    const bool ran = std::any_of(manifests.begin(), manifests.end(), [&](const auto& m) {
      return m["of"].template get<std::size_t>() == of && m["task"].template get<std::size_t>() == s.index;
    });
    owed.push_back(fmt::format("shard {} {}", s.text(), ran ? "did not finish it" : "has not run"));
  }
  return fmt::format("{}", fmt::join(owed, ", "));
}

// The sweep tables (one per series value: the swept value, then every
// headline figure of the runs), the study's sweep plots and summary.json.
// `failures` (one per run, "" if it ran) marks the runs that failed: a
// column `failed` and the list in summary.json; no plots then.
// `tasks`: which rank ran each run, on how many threads, for how long (null: not known, as when merged).
void publish_sweep(SweepPlan& plan, Config& probe, const std::vector<std::string>& failures,
                   const nlohmann::json& tasks = nullptr) {
  RunSummary& sweep = plan.sweep;
  std::vector<PreparedRun>& runs = plan.runs;
  const std::string& key = sweep.sweep_key;
  const std::vector<std::string>& values = plan.values;
  const std::vector<std::string>& run_value = sweep.sweep_values;
  const std::vector<std::string>& run_series = plan.run_series;
  const std::string& series_key = plan.series_key;
  const std::string& table_name = plan.table_name;
  const bool any_failed = std::any_of(failures.begin(), failures.end(), [](const std::string& f) { return !f.empty(); });
  OutputSet outputs(sweep.output_dir, "summary.json");
  for (const auto& folder : run_folders_of(plan)) outputs.own_folder(folder);  // the sweep's runs: its set
  std::vector<std::string> names, result_units;
  for (const auto& r : runs)
    for (const auto& [name, v] : r.summary.results.items())
      if (std::find(names.begin(), names.end(), name) == names.end()) {
        names.push_back(name);
        // A headline figure's unit: SI, "1" or "" when it has none (a count, a ratio).
        const std::string unit = v.contains("unit") ? v["unit"].get<std::string>() : "";
        result_units.push_back(unit.empty() ? "1" : unit);
      }
  if (any_failed) {
    names.push_back("failed");
    result_units.push_back("1");
  }
  // The swept values as numbers in SI, in the dimension the case reads the key in (a bare number is SI
  // in it: a thickness of 1e-6 is metres), if they all are numbers (else the tables keep the text).
  std::vector<double> numeric;
  std::optional<units::Dimension> swept_dimension = runs.front().cfg.dimension_of(key);
  if (swept_dimension) {
    for (std::size_t k = 0; k < values.size(); ++k) try {
        numeric.push_back(runs[k].cfg.number(key, Range::any().or_infinite(), *swept_dimension));
      } catch (const std::exception&) {
        numeric.clear();
        break;
      }
  } else {  // a key no number getter read (an integer, a choice): its values as written
    for (const auto& v : values) try {
        const auto q = units::parse_quantity(v);
        if (swept_dimension && !(*swept_dimension == q.dimension)) throw std::invalid_argument("mixed dimensions");
        swept_dimension = q.dimension;
        numeric.push_back(q.value);
      } catch (const std::exception&) {
        numeric.clear();
        break;
      }
  }
  const bool numeric_values = numeric.size() == values.size();
  const std::string column = swept_column(key);
  std::vector<std::pair<std::string, std::filesystem::path>> tables;  // label, file
  for (std::size_t first = 0; first < runs.size(); first += values.size()) {
    std::vector<std::vector<double>> columns(names.size());
    for (std::size_t k = first; k < first + values.size(); ++k)
      for (std::size_t c = 0; c < names.size(); ++c) {
        const auto& res = runs[k].summary.results;
        if (any_failed && c + 1 == names.size())
          columns[c].push_back(failures[k].empty() ? 0.0 : 1.0);
        else
          columns[c].push_back(res.contains(names[c]) ? res[names[c]]["value"].get<double>() : std::nan(""));
      }
    std::vector<std::span<const double>> spans;
    if (numeric_values) spans.emplace_back(numeric);
    for (const auto& c : columns) spans.emplace_back(c);
    const std::filesystem::path base(table_name);
    const std::string label = series_key.empty() ? "" : label_of(series_key, run_series[first]);
    const auto table = sweep.output_dir / (label.empty() ? base : std::filesystem::path(base.stem().string() + "_" + label +
                                                                                        base.extension().string()));
    std::vector<std::string> comments{
        fmt::format("sweep of case '{}' over {} (column {}); SI units unless a column's name says otherwise; nan: "
                    "not reached",
                    sweep.case_name, key,
                    numeric_values ? csv_column_name(column, swept_dimension->to_string()) : column)};
    if (!label.empty()) comments.push_back(fmt::format("series: {} = {}", series_key, run_series[first]));
    if (any_failed) comments.push_back("failed = 1: the run failed (summary.json lists why); its figures are nan");
    if (numeric_values) {
      std::vector<std::string> header{column}, header_units{swept_dimension->to_string()};
      header.insert(header.end(), names.begin(), names.end());
      header_units.insert(header_units.end(), result_units.begin(), result_units.end());
      write_csv(table, header, spans, header_units, comments);
    } else {
      write_csv(table, column, values, names, spans, result_units, comments);
    }
    sweep.files.push_back(table);
    tables.push_back({label.empty() ? "model" : label, table});
  }

  Study::SweepRuns view;
  view.probe = &probe;
  view.key = key;
  view.series_key = series_key;
  view.numeric_values = numeric_values;
  view.result_names = names;
  view.case_name = sweep.case_name;
  view.output_dir = sweep.output_dir;
  for (const auto& t : tables) view.tables.emplace_back(t.first, t.second);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    sweep.runs.push_back(runs[k].summary);
    view.folders.push_back(runs[k].summary.output_dir);
    view.labels.push_back(label_of(key, run_value[k]) + (series_key.empty() ? "" : " " + label_of(series_key, run_series[k])));
    view.values.push_back(run_value[k]);
    view.series_values.push_back(series_key.empty() ? std::string() : run_series[k]);
  }
  if (any_failed)
    log::warn("{}: no sweep plots (some runs failed)", sweep.output_dir.string());
  else
    for (auto& f : runs.front().study->finish_sweep(view)) sweep.files.push_back(std::move(f));
  sweep.files.push_back(sweep.output_dir / "summary.json");
  nlohmann::json summary = sweep.to_json();
  if (!tasks.is_null()) summary["tasks"] = tasks;
  if (any_failed) {
    summary["failed"] = nlohmann::json::array();
    for (std::size_t k = 0; k < runs.size(); ++k)
      if (!failures[k].empty())
        summary["failed"].push_back({{"run", k + 1}, {"value", run_value[k]},
                                     {"output_dir", runs[k].summary.output_dir.string()}, {"error", failures[k]}});
  }
  outputs.commit(summary);
}

// The runs of a sweep, or of one shard of it. Without mpirun: side by side on
// threads within the -j budget (the first failure ends the sweep, as a single
// run's does). Under mpirun: over the ranks by the task farm (a failed run is
// marked in the table). A shard writes no shared file but its manifest; the
// whole sweep (one job, any number of ranks) writes the tables and summary.
RunSummary run_sweep(const CaseLoader& parse, const RunOptions& options, Config& probe, int threads,
                     const std::optional<Shard>& shard) {
  std::optional<SweepPlan> planned;
  mpi::refuse_together([&] {
    const mpi::Alone alone;  // each run of a sweep runs on one rank (a task of the farm): so is it prepared
    planned = plan_sweep(parse, options, probe);
    describe_sweep(*planned, options);
  });
  SweepPlan& plan = *planned;
  RunSummary& sweep = plan.sweep;
  std::vector<PreparedRun>& runs = plan.runs;
  const std::string& key = sweep.sweep_key;
  const bool farmed = mpi::size() > 1;
  std::vector<std::size_t> mine;  // the runs this job runs
  for (std::size_t k = 0; k < runs.size(); ++k)
    if (!shard || shard->owns(k)) mine.push_back(k);
  // Resuming, every checkpoint is read (and its FFT plans imported) before any run makes a plan.
  const std::string command = command_line(options, threads);
  const std::string ensemble = ensemble_id(plan);
  std::optional<OutputLock> lock;
  mpi::refuse_together([&] {  // the folder and what is in it: rank 0's
    if (!mpi::is_root()) return;
    lock.emplace(shard ? OutputLock::folder(sweep.output_dir, command, OutputLock::Mode::Shared, ensemble)
                       : OutputLock::folder(sweep.output_dir, command));
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
  });
  FFTPlanCache::global().set_rigor(runs.front().fft_rigor);
  std::vector<std::string> failures(runs.size());
  nlohmann::json tasks = nlohmann::json::array();  // per run: rank, threads, wall time
  const auto add_task = [&](std::size_t k, int rank, int run_threads, double seconds) {
    tasks.push_back({{"run", k + 1}, {"rank", rank}, {"threads", run_threads}, {"seconds", seconds}});
  };
  const std::string what = shard ? fmt::format("shard {} of the sweep", shard->text()) : std::string("sweep");
  bool any_output_failure = false;  // a farmed run failed to write its outputs: status 2

  if (farmed) {
    log::info("{} over {}: {} runs on {} MPI ranks × {} thread(s) → {}", what, key, mine.size(), mpi::size(),
              thread_budget(), sweep.output_dir.string());
    mpi::FarmOptions farm_options;
    farm_options.label = what;
    farm_options.stop = [] { return interrupt_requested(); };
    farm_options.root_computes =
        std::none_of(runs.begin(), runs.end(), [](const PreparedRun& r) { return r.study->calls_mpi(); });
    const auto outcome = mpi::farm(
        mine.size(),
        [&](std::size_t t) {
          PreparedRun& run = runs[mine[t]];
          if (options.resume_dir && !run.checkpoints) find_resume_point(run);  // rank 0 found them all above
          execute(run, options, false, &command);
          return run_message(run.summary).dump();
        },
        farm_options);
    if (outcome.not_run > 0) {  // stopped by a signal: checkpoints saved, resume continues
      const Interrupted e(fmt::format("{} stopped by a signal: {} of {} runs not finished", what, outcome.not_run,
                                      mine.size()));
      rethrow_interrupted(e, command, sweep.output_dir);
    }
    // A run that could not write its outputs (a full disk) ends the job with status 2 on every rank, as a
    // serial run's would; rank 0 alone knows the failures, and tells.
    bool output_failed = false;
    if (mpi::is_root())
      for (const auto& r : outcome.results) output_failed = output_failed || r.output;
    output_failed = mpi::sum(output_failed ? 1LL : 0LL) > 0;
    if (!mpi::is_root()) {
      if (outcome.failed > 0) throw mpi::TasksFailed("", false, output_failed);
      return sweep;
    }
    any_output_failure = output_failed;
    for (std::size_t t = 0; t < mine.size(); ++t) {
      const auto& r = outcome.results[t];
      add_task(mine[t], r.rank, r.threads, r.seconds);
      if (r.status == mpi::TaskResult::Status::Done)
        take_run_message(runs[mine[t]].summary, nlohmann::json::parse(r.text));
      else
        failures[mine[t]] = fmt::format("{} (rank {})", r.text, r.rank);
    }
  } else {
    // The thread budget (-j) shared out: runs side by side, the rest inside each run.
    const unsigned budget = static_cast<unsigned>(threads);
    const unsigned workers = plan.parallel ? std::min<unsigned>(budget, static_cast<unsigned>(std::max<std::size_t>(1, mine.size()))) : 1u;
    const int per_run = static_cast<int>(std::max(1u, budget / workers));
    if (workers > 1) FFTPlanCache::global().set_threads(per_run);
    log::info("{} over {}: {} runs on {} worker(s) × {} thread(s) → {}", what, key, mine.size(), workers, per_run,
              sweep.output_dir.string());
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
    for (std::size_t t = 0; t < mine.size(); ++t) add_task(mine[t], 0, workers > 1 ? per_run : static_cast<int>(budget), seconds[t]);
    progress.finish();
    try {
      throw_if_interrupted("sweep");  // also when the signal came between runs
      for (auto& e : errors)
        if (e) std::rethrow_exception(e);
    } catch (const Interrupted& e) {
      rethrow_interrupted(e, command, sweep.output_dir);
    }
  }

  if (shard) {  // its own runs only; `wearscale merge` writes the tables once every shard is done
    RunSummary part = sweep;
    part.sweep_values.clear();
    part.series_values.clear();
    part.files = {sweep.output_dir / manifest_name(*shard)};
    for (const auto k : mine) {
      part.runs.push_back(runs[k].summary);
      part.sweep_values.push_back(sweep.sweep_values[k]);
      if (!plan.series_key.empty()) part.series_values.push_back(sweep.series_values[k]);
    }
    std::vector<std::string> failed;
    for (const auto k : mine)
      if (!failures[k].empty()) failed.push_back(fmt::format("run {} ({}={}): {}", k + 1, key, sweep.sweep_values[k], failures[k]));
    if (!failed.empty())
      throw mpi::TasksFailed(fmt::format("{}: {} of its {} runs failed: {}; rerun them with: {} --resume {}", what,
                                         failed.size(), mine.size(), fmt::join(failed, "; "), command,
                                         sweep.output_dir.string()),
                             true, any_output_failure);
    log::info("shard {} done; once every shard is: wearscale merge {}", shard->text(), sweep.output_dir.string());
    return part;
  }
  publish_sweep(plan, probe, failures, tasks);
  std::vector<std::string> failed;
  for (std::size_t k = 0; k < runs.size(); ++k)
    if (!failures[k].empty()) failed.push_back(fmt::format("run {} ({}={}): {}", k + 1, key, sweep.sweep_values[k], failures[k]));
  if (!failed.empty())
    throw mpi::TasksFailed(fmt::format("{}: {} of {} runs failed, marked in the table (failed = 1): {}; rerun them "
                                       "with: {} --resume {}",
                                       what, failed.size(), runs.size(), fmt::join(failed, "; "), command,
                                       sweep.output_dir.string()),
                           true, any_output_failure);
  return sweep;
}

// Under `mpirun -np P` (P > 1): one run of a distributed study, every rank in
// it. Every check (the case, the study's keys, rank 0's output folder) is
// agreed by all ranks before any work (mpi::refuse_together: a refusal ends
// every rank with status 2, nothing written); then rank 0 runs the study into
// its folder as a single run does and the other ranks make the same
// collective calls (Study::run_other_rank), writing nothing.
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

// merge of one run's shards: the run once more, every task of its ensembles
// taken from what the shards kept (none computed), its outputs written as an
// unsharded run writes them; refused, naming them, while tasks are missing.
RunSummary merge_run(const std::filesystem::path& dir, Config probe, const RunOptions& options,
                     const std::vector<nlohmann::json>& manifests) {
  if (probe.has("sweep"))
    throw InputError(fmt::format("merge {}: the shards ran one case without a [sweep], which has one now", dir.string()));
  PreparedRun run = prepare(std::move(probe), dir, options);
  if (ensemble_id(run) != manifests.front()["ensemble"].get<std::string>())
    throw InputError(fmt::format("merge {}: the case ({}) is not the one the shards ran (it changed since); merge "
                                 "with the case they ran, or run the ensemble again",
                                 dir.string(), options.case_file.empty() ? "the command's keys" : options.case_file.string()));
  const OutputLock lock = OutputLock::folder(dir, options.command);  // refused while a shard still runs
  find_resume_point(run);
  if (run.complete) {
    log::info("merge {}: the run is already complete", dir.string());
    return run.summary;
  }
  run.tasks = mpi::TaskStore::Mode::Assemble;
  run.owner = [&](std::size_t k) { return owner_of(k, manifests); };
  FFTPlanCache::global().set_rigor(run.fft_rigor);
  try {
    execute(run, options, true, nullptr);
  } catch (const OutputError&) {
    throw;
  } catch (const InputError& e) {
    throw InputError(fmt::format("merge {}: {}; run what is left (the shards named, or all of it with --resume {}), "
                                 "then merge again",
                                 dir.string(), e.what(), dir.string()));
  }
  log::info("merged the tasks of {} shard(s) into {}", manifests.size(), dir.string());
  return run.summary;
}

// One shard of a run's ensembles (--task K/N, no mpirun): its share of every
// ensemble the run meets, kept in tasks/ beside the other shards'; it stops
// at the first ensemble that lacks theirs (exit 0), writing none of the
// run's outputs (merge does).
RunSummary run_shard(PreparedRun& run, const RunOptions& options, const Shard& shard) {
  if (!run.study->has_ensembles())
    throw InputError(fmt::format("--task {}: study '{}' runs one task, not an ensemble; --task K/N shards the runs "
                                 "of a [sweep], a rough wear map's surfaces, nano/dem's junction runs and a "
                                 "strength table's points (run it without --task)",
                                 shard.text(), run.summary.study));
  const std::string command = command_line(options, thread_budget());
  const std::string ensemble = ensemble_id(run);
  const auto& dir = run.summary.output_dir;
  const OutputLock lock = OutputLock::folder(dir, command, OutputLock::Mode::Shared, ensemble);
  if (options.resume_dir) find_resume_point(run);
  if (run.complete) return run.summary;
  write_manifest(dir, shard, ensemble, run.summary.study, options, command, {{"kind", "run"}});
  run.tasks = mpi::TaskStore::Mode::Shard;
  run.shard = shard.index, run.shards = shard.of;
  FFTPlanCache::global().set_rigor(run.fft_rigor);
  log::info("case '{}': shard {} of its ensembles → {}", run.summary.case_name, shard.text(), dir.string());
  try {
    execute(run, options, true, nullptr);
  } catch (const mpi::ShardDone& e) {
    log::info("shard {} done ({}); once every shard is: wearscale merge {}", shard.text(), e.what(), dir.string());
  } catch (const Interrupted& e) {
    rethrow_interrupted(e, command, dir);
  }
  RunSummary part = run.summary;
  part.results = nlohmann::json::object();
  part.files = {dir / manifest_name(shard)};
  return part;
}

}  // namespace

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

RunSummary merge_shards(const std::filesystem::path& dir, const std::string& command) {
  require_utf8_path(dir, "merge");
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw InputError(fmt::format("merge {}: not a folder; allowed: the output folder of an ensemble's shards "
                                 "(wearscale run CASE --task K/N --out DIR)",
                                 dir.string()));
  // The shards' manifests: task-K-of-N.json.
  std::vector<nlohmann::json> manifests;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with("task-") || !name.ends_with(".json") || name.find("-of-") == std::string::npos) continue;
    try {
      manifests.push_back(nlohmann::json::parse(read_text_file(entry.path(), "shard manifest", std::uintmax_t{1} << 26)));
      const auto& m = manifests.back();
      (void)m.at("ensemble").get<std::string>(), (void)m.at("task").get<std::size_t>(), (void)m.at("of").get<std::size_t>();
    } catch (const nlohmann::json::exception& e) {
      throw InputError(fmt::format("{}: not a shard manifest of wearscale ({})", entry.path().string(), e.what()));
    }
  }
  if (manifests.empty())
    throw InputError(fmt::format("merge {}: no shard has run into this folder (no task-K-of-N.json); allowed: the "
                                 "output folder of an ensemble's shards (wearscale run CASE --task K/N --out DIR)",
                                 dir.string()));
  std::sort(manifests.begin(), manifests.end(), [](const auto& a, const auto& b) {
    return std::pair(a["of"].template get<std::size_t>(), a["task"].template get<std::size_t>()) <
           std::pair(b["of"].template get<std::size_t>(), b["task"].template get<std::size_t>());
  });
  const nlohmann::json& first = manifests.front();
  for (const auto& m : manifests)
    if (m["ensemble"] != first["ensemble"])
      throw InputError(fmt::format("merge {}: shards {}/{} and {}/{} ran different cases (ensemble ids differ); a "
                                   "folder holds the shards of one ensemble",
                                   dir.string(), first["task"].get<std::size_t>(), first["of"].get<std::size_t>(),
                                   m["task"].get<std::size_t>(), m["of"].get<std::size_t>()));
  // The case as the shards ran it: the case file if it is still where it was, else the text they recorded.
  RunOptions options;
  options.study = first.value("study", "");
  options.case_file = first.value("case_file", "");
  options.flags = first.value("flags", std::vector<std::pair<std::string, std::string>>{});
  options.overrides = first.value("overrides", std::vector<std::string>{});
  options.output_dir = dir;
  options.command = command;
  const std::filesystem::path absolute = first.value("case_file_absolute", "");
  const std::string text = first.value("case_text", "");
  const CaseLoader parse = [&] {
    if (!options.case_file.empty() && std::filesystem::exists(options.case_file)) return Config::load(options.case_file);
    if (!absolute.empty() && std::filesystem::exists(absolute)) return Config::load(absolute);
    return Config::from_string(text, options.case_file.empty() ? "<command line>" : options.case_file.string());
  };
  Config probe = load(parse, options);
  if (first.value("kind", "sweep") == "run") return merge_run(dir, std::move(probe), options, manifests);
  if (!probe.has("sweep"))
    throw InputError(fmt::format("merge {}: the shards' case has no [sweep] any more", dir.string()));
  SweepPlan plan = plan_sweep(parse, options, probe);
  describe_sweep(plan, options);
  if (ensemble_id(plan) != first["ensemble"].get<std::string>())
    throw InputError(fmt::format("merge {}: the case ({}) is not the one the shards ran (it changed since); merge "
                                 "with the case they ran, or run the ensemble again",
                                 dir.string(), options.case_file.empty() ? "the command's keys" : options.case_file.string()));
  const OutputLock lock = OutputLock::folder(dir, command);  // refused while a shard still runs
  std::vector<std::string> missing;
  for (std::size_t k = 0; k < plan.runs.size(); ++k) {
    find_resume_point(plan.runs[k]);
    if (plan.runs[k].complete) continue;
    missing.push_back(fmt::format("task {} ({}: {})", k + 1, plan.runs[k].summary.output_dir.filename().string(),
                                  owner_of(k, manifests)));
  }
  if (!missing.empty())
    throw InputError(fmt::format("merge {}: {} of {} tasks are not complete: {}; run what is left (any shard count) "
                                 "with --resume {}, then merge again",
                                 dir.string(), missing.size(), plan.runs.size(), fmt::join(missing, "; "), dir.string()));
  publish_sweep(plan, probe, std::vector<std::string>(plan.runs.size()));
  log::info("merged {} runs of {} shard(s) into {}", plan.runs.size(), manifests.size(), dir.string());
  return plan.sweep;
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
