#include "wearscale/studies/runner.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <fstream>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/fft.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/core/output_lock.hpp"
#include "wearscale/core/output_set.hpp"
#include "wearscale/core/progress.hpp"
#include "wearscale/core/text_file.hpp"
#include "wearscale/core/units.hpp"
#include "wearscale/core/utf8.hpp"
#include "wearscale/core/worker_pool.hpp"
#include "wearscale/io/checkpoint.hpp"
#include "wearscale/io/config.hpp"
#include "wearscale/io/csv.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/studies/study.hpp"

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
};

// The study a case runs: the one its command names, else the one it names.
std::unique_ptr<Study> study_for(const Config& cfg, const RunOptions& options) {
  cfg.mark_used("case.study");
  return study_registry().create(options.study.empty() ? study_of(cfg) : options.study);
}

// Paths from the command line end up in summary.json, which holds UTF-8 only.
void require_utf8_paths(const RunOptions& options) {
  require_utf8_path(options.case_file, "case file");
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

PreparedRun prepare(Config cfg_in, const std::optional<std::filesystem::path>& out, const RunOptions& options) {
  PreparedRun run{std::move(cfg_in), {}, {}, {}, PlanRigor::Measure, {}, std::nullopt, false, false};
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
  run.summary.scales = run.study->prepare(cfg);
  run.summary.parameters = cfg.to_json();
  run.fingerprint = case_fingerprint(run.summary.parameters);
  return run;
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
  run.summary.results = j.value("results", nlohmann::json::object());
  for (const auto& [key, value] : j.items())  // the study's own fields
    if (!RunSummary{}.to_json().contains(key) && key != "results") run.summary.notes[key] = value;
  for (const auto& f : j.value("files", nlohmann::json::array()))
    if (f.is_string()) run.summary.files.emplace_back(f.get<std::string>());
  run.complete = true;
  run.summary.complete_before = true;
}

// A fresh run never throws away the checkpoint of an unfinished one.
void check_fresh_start(const PreparedRun& run) { require_fresh_start(run.summary.output_dir / "checkpoint.h5"); }

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
  run.study->run(run.cfg, context);
  for (const auto& [name, r] : context.results().items()) {
    const double value = r["value"].get<double>();
    if (!std::isfinite(value))  // never a NaN (null in JSON) or infinite headline figure
      throw NumericalError("case " + summary.case_name, 0, name, fmt::format("the result is {}", value));
    h5.write_scalar("/results/" + name, value, r["unit"].get<std::string>());
    h5.set_attribute("/results/" + name, "description", r["description"].get<std::string>());
  }
  summary.results = context.results();
  summary.notes = context.notes();
  summary.files = context.files();
  h5.commit();
  summary.files.insert(summary.files.begin(), h5.final_path());
  summary.files.push_back(summary.output_dir / "summary.json");
  outputs.commit(summary.to_json());
  if (run.checkpoints->saves() > 0)
    log::debug("{}: {} checkpoints written in {:.3f} s", summary.output_dir.string(), run.checkpoints->saves(),
               run.checkpoints->seconds_saving());
  run.checkpoints->discard();  // complete: nothing to resume
  if (run.resume) remove_stale_partials(summary.output_dir);  // those this run did not continue
}

// How to continue an interrupted run, added to the Interrupted message.
[[noreturn]] void rethrow_interrupted(const Interrupted& e, const std::string& command,
                                      const std::filesystem::path& dir) {
  throw Interrupted(fmt::format("{}; continue with: {} --resume {}", e.what(), command, dir.string()));
}

std::string label_of(const std::string& key, const std::string& value) {
  std::string leaf = key.substr(key.rfind('.') + 1) + "=" + value;
  for (auto& c : leaf)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '=' || c == '.' || c == '-' || c == '+' || c == '_'))
      c = '_';
  return leaf;
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
  for (std::size_t a = 0; a < values.size(); ++a)
    for (std::size_t b = 0; b < a; ++b) {
      bool same = values[a] == values[b] || labels[a] == labels[b];
      try {  // "1 um" and 1e-6 are one run too
        same = same || units::parse_quantity(values[a]).value == units::parse_quantity(values[b]).value;
      } catch (const std::exception&) {
      }
      if (same)
        throw probe.error("sweep.values",
                          fmt::format("values {} ('{}') and {} ('{}') are the same run (folder {})", b + 1, values[b],
                                      a + 1, values[a], labels[a]),
                          "distinct values");
    }
  const bool plain = !table_name.empty() && table_name.front() != '.' && table_name.find('/') == std::string::npos &&
                     table_name.find('\0') == std::string::npos;
  if (!plain || table_name == "summary.json" || std::find(labels.begin(), labels.end(), table_name) != labels.end())
    throw probe.error("sweep.table", "not a file name for the sweep table",
                      "a plain file name in the sweep's folder (no '/', not hidden, not summary.json or a run's folder)");
}

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
  // Every run is checked before any starts.
  const std::string where = probe.where("sweep.values");
  std::vector<std::string> run_value;
  for (const auto& sv : series) {
    const auto folder =
        plan.series_key.empty() ? sweep.output_dir : sweep.output_dir / label_of(plan.series_key, sv);
    for (std::size_t k = 0; k < values.size(); ++k) {
      std::vector<std::pair<std::string, std::string>> extra{
          {key + "=" + values[k], fmt::format("{} (sweep.values[{}])", where, k)}};
      if (!plan.series_key.empty()) extra.push_back({plan.series_key + "=" + sv, probe.where("sweep.series.values")});
      plan.runs.push_back(prepare(load(parse, options, extra), folder / plan.labels[k], options));
      run_value.push_back(values[k]);
      plan.run_series.push_back(sv);
    }
  }
  sweep.sweep_values = run_value;
  if (!plan.series_key.empty()) sweep.series_values = plan.run_series;
  return plan;
}

RunSummary run_sweep(const CaseLoader& parse, const RunOptions& options, Config& probe, int threads) {
  SweepPlan plan = plan_sweep(parse, options, probe);
  RunSummary& sweep = plan.sweep;
  std::vector<PreparedRun>& runs = plan.runs;
  const std::string& key = sweep.sweep_key;
  const std::vector<std::string>& values = plan.values;            // the swept key's values
  const std::vector<std::string>& run_value = sweep.sweep_values;  // ... of each run
  const std::vector<std::string>& run_series = plan.run_series;
  const std::string& series_key = plan.series_key;
  const std::vector<std::string>& series = plan.series;
  const std::string& table_name = plan.table_name;
  const bool parallel = plan.parallel;
  // Resuming, every checkpoint is read (and its FFT plans imported) before any run makes a plan.
  const std::string command = command_line(options, threads);
  const OutputLock lock = OutputLock::folder(sweep.output_dir, command);
  if (options.resume_dir) {
    for (auto& r : runs) find_resume_point(r);
    const auto finished = std::count_if(runs.begin(), runs.end(), [](const PreparedRun& r) { return r.complete; });
    log::info("resuming the sweep in {}: {} of {} runs complete", sweep.output_dir.string(), finished, runs.size());
  } else {
    for (const auto& r : runs) check_fresh_start(r);
  }
  FFTPlanCache::global().set_rigor(runs.front().fft_rigor);
  sweep.scales = runs.front().summary.scales;
  sweep.provenance = provenance_of(sweep, options);
  sweep.parameters = runs.front().summary.parameters;
  sweep.parameters["sweep"] = {{"key", key}, {"values", values}};
  if (!series_key.empty()) sweep.parameters["sweep"]["series"] = {{"key", series_key}, {"values", series}};

  // The thread budget (-j) shared out: runs side by side, the rest inside each run.
  const unsigned budget = static_cast<unsigned>(threads);
  const unsigned workers = parallel ? std::min<unsigned>(budget, static_cast<unsigned>(runs.size())) : 1u;
  const int per_run = static_cast<int>(std::max(1u, budget / workers));
  if (workers > 1) FFTPlanCache::global().set_threads(per_run);
  log::info("sweep over {}: {} runs on {} worker(s) × {} thread(s) → {}", key, runs.size(), workers, per_run,
            sweep.output_dir.string());
  std::vector<std::exception_ptr> errors(runs.size());
  std::size_t done = 0;
  std::mutex progress_mutex;
  Progress progress("sweep", static_cast<double>(runs.size()), "runs");
  WorkerOptions pool;
  pool.workers = workers;
  pool.omp_threads = workers > 1 ? per_run : 0;
  pool.caller_omp_too = true;
  pool.stop = [] { return interrupt_requested(); };
  run_on_workers(runs.size(), pool, [&](std::size_t k) {
    try {
      execute(runs[k], options, false, &command);
    } catch (...) {
      errors[k] = std::current_exception();
    }
    std::lock_guard guard(progress_mutex);
    progress.update(static_cast<double>(++done));
  });
  progress.finish();
  try {
    throw_if_interrupted("sweep");  // also when the signal came between runs
    for (auto& e : errors)
      if (e) std::rethrow_exception(e);
  } catch (const Interrupted& e) {
    rethrow_interrupted(e, command, sweep.output_dir);
  }

  // The sweep tables (one per series value): the swept value, then every
  // headline figure of the runs.
  OutputSet outputs(sweep.output_dir, "summary.json");
  std::vector<std::string> names, result_units;
  for (const auto& r : runs)
    for (const auto& [name, v] : r.summary.results.items())
      if (std::find(names.begin(), names.end(), name) == names.end()) {
        names.push_back(name);
        // A headline figure's unit: SI, "1" or "" when it has none (a count, a ratio).
        const std::string unit = v.contains("unit") ? v["unit"].get<std::string>() : "";
        result_units.push_back(unit.empty() ? "1" : unit);
      }
  // The swept values as numbers in SI, if they all are and share one dimension (else the tables keep the text).
  std::vector<double> numeric;
  std::optional<units::Dimension> swept_dimension;
  for (const auto& v : values) try {
      const auto q = units::parse_quantity(v);
      if (swept_dimension && !(*swept_dimension == q.dimension)) throw std::invalid_argument("mixed dimensions");
      swept_dimension = q.dimension;
      numeric.push_back(q.value);
    } catch (const std::exception&) {
      numeric.clear();
      break;
    }
  const bool numeric_values = numeric.size() == values.size();
  std::vector<std::pair<std::string, std::filesystem::path>> tables;  // label, file
  for (std::size_t first = 0; first < runs.size(); first += values.size()) {
    std::vector<std::vector<double>> columns(names.size());
    for (std::size_t k = first; k < first + values.size(); ++k)
      for (std::size_t c = 0; c < names.size(); ++c) {
        const auto& res = runs[k].summary.results;
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
        fmt::format("sweep of case '{}' over {} (SI units; nan: not reached)", sweep.case_name, key)};
    if (!label.empty()) comments.push_back(fmt::format("series: {} = {}", series_key, run_series[first]));
    if (numeric_values) {
      std::vector<std::string> header{key}, header_units{swept_dimension->to_string()};
      header.insert(header.end(), names.begin(), names.end());
      header_units.insert(header_units.end(), result_units.begin(), result_units.end());
      write_csv(table, header, spans, header_units, comments);
    } else {
      write_csv(table, key, values, names, spans, result_units, comments);
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
  }
  for (auto& f : runs.front().study->finish_sweep(view)) sweep.files.push_back(std::move(f));
  sweep.files.push_back(sweep.output_dir / "summary.json");
  outputs.commit(sweep.to_json());
  return sweep;
}

// Under `mpirun -np P` (P > 1): one run of a distributed study, every rank in
// it. Every check (the case, the study's keys, rank 0's output folder) is
// agreed by all ranks before any work (mpi::refuse_together: a refusal ends
// every rank with status 2, nothing written); then rank 0 runs the study into
// its folder as a single run does and the other ranks make the same
// collective calls (Study::run_other_rank), writing nothing.
RunSummary run_distributed(const RunOptions& options) {
  std::optional<PreparedRun> run;
  std::optional<OutputLock> lock;
  const std::string command = command_line(options, thread_budget());
  mpi::refuse_together([&] {
    require_utf8_paths(options);
    if (options.resume_dir)
      throw InputError(fmt::format("--resume {}: a run on {} MPI ranks writes no checkpoints and is not resumed; run "
                                   "it again, or resume a run made without mpirun without mpirun",
                                   options.resume_dir->string(), mpi::size()));
    Config cfg = options.case_text ? Config::from_string(*options.case_text, options.case_file.string())
                 : options.case_file.empty() ? Config::from_string("", "<command line>")
                                             : Config::load(options.case_file);
    for (const auto& o : options.overrides) cfg.override_value(o);
    if (cfg.has("sweep"))
      throw cfg.error("sweep.key", fmt::format("a sweep is not distributed over MPI ranks ({} ranks started)", mpi::size()),
                      "no [sweep] under mpirun; a sweep without mpirun");
    run.emplace(prepare(std::move(cfg), options.output_dir, options));
    if (!run->study->distributed())
      throw InputError(fmt::format("study '{}' runs on one rank only ({} ranks started; under mpirun only the contact "
                                   "study is distributed); run it without mpirun",
                                   run->summary.study, mpi::size()));
  });
  mpi::refuse_together([&] {  // the folder: rank 0's alone
    if (!mpi::is_root()) return;
    lock.emplace(OutputLock::folder(run->summary.output_dir, command));
    check_fresh_start(*run);
  });
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

}  // namespace

RunSummary run_case(const RunOptions& options_in) {
  if (mpi::size() > 1) return run_distributed(options_in);
  require_utf8_paths(options_in);
  RunOptions options = options_in;
  if (options.resume_dir)
    options.output_dir = resume_folder(*options.resume_dir, options.output_dir.value_or(std::filesystem::path()));
  const int threads = thread_budget();
  const CaseLoader parse = [&] {
    if (options.case_text) return Config::from_string(*options.case_text, options.case_file.string());
    return options.case_file.empty() ? Config::from_string("", "<command line>") : Config::load(options.case_file);
  };
  Config probe = load(parse, options);
  if (probe.has("sweep")) return run_sweep(parse, options, probe, threads);
  PreparedRun run = prepare(std::move(probe), options.output_dir, options);  // a single run: the file is parsed once
  const std::string command = command_line(options, threads);
  const OutputLock lock = OutputLock::folder(run.summary.output_dir, command);
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

}  // namespace wearscale::studies
