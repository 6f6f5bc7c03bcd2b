#include "wearscale/coupling/case_runner.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <ctime>
#include <exception>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/checkpoint.hpp"
#include "wearscale/core/config.hpp"
#include "wearscale/core/csv.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/fft.hpp"
#include "wearscale/core/hdf5_file.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/progress.hpp"
#include "wearscale/core/units.hpp"
#include "wearscale/coupling/pipeline.hpp"
#include "wearscale/coupling/plots.hpp"

namespace wearscale::coupling {

nlohmann::json RunSummary::to_json() const {
  std::vector<std::string> names;
  for (const auto& f : files) names.push_back(f.string());
  nlohmann::json j = {{"case", case_name}, {"output_dir", output_dir.string()}, {"scales", scales},
                      {"files", names}, {"parameters", parameters}};
  if (sweep_key.empty()) {
    j["results"] = results;
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

std::string utc_now() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

Config load(const RunOptions& options, const std::vector<std::string>& extra) {
  Config cfg = Config::load(options.case_file);
  for (const auto& o : options.overrides) cfg.override_value(o);
  for (const auto& o : extra) cfg.override_value(o);
  return cfg;
}

Pipeline build_pipeline(const Config& cfg) {
  const auto& registry = scale_registry();
  const auto kinds = cfg.keys("scale");
  if (kinds.empty())
    throw InputError(fmt::format("{}: the case has no [scale.<kind>] table; known kinds: {}", cfg.source(),
                                 fmt::join(registry.kinds(), ", ")));
  Pipeline pipeline;
  for (const auto& kind : kinds) {
    const Config section = cfg.section("scale." + kind);
    const auto names = registry.names(kind);
    if (names.empty())
      throw cfg.error("scale." + kind, "unknown scale kind", fmt::format("{}", fmt::join(registry.kinds(), ", ")));
    const std::string backend = section.string("backend");
    if (!registry.contains(kind, backend))
      throw section.error("backend", "unknown backend", fmt::format("{}", fmt::join(names, ", ")));
    const ScaleSetup setup{kind, backend, section, cfg};
    pipeline.add(kind + "/" + backend, registry.create(kind, backend, setup));
  }
  pipeline.order();
  return pipeline;
}

// A case checked and ready to run: every key read, every scale built.
struct PreparedRun {
  Config cfg;
  Pipeline pipeline;
  RunSummary summary;
  CheckpointPolicy policy;
  PlanRigor fft_rigor = PlanRigor::Measure;
  std::string fingerprint;                 // the parameters that determine the results
  std::optional<Checkpointer> checkpoints;
  bool resume = false;                     // continues from its checkpoint
  bool complete = false;                   // resumed, but it had finished: its outputs stand
};

PreparedRun prepare(Config cfg_in, const std::optional<std::filesystem::path>& out) {
  PreparedRun run{std::move(cfg_in), {}, {}, {}, PlanRigor::Measure, {}, std::nullopt, false, false};
  Config& cfg = run.cfg;
  run.summary.case_name = cfg.string("case.name");
  cfg.string_or("case.description", "");
  const std::string case_dir = cfg.string_or("output.dir", "out/" + run.summary.case_name);
  run.summary.output_dir = out ? *out : std::filesystem::path(case_dir);
  cfg.mark_used("sweep");  // read by run_case
  // [run]: how the run is carried out, not what it computes.
  run.policy = checkpoint_policy(cfg);
  const Config r = cfg.section("run");
  run.fft_rigor = r.choice_or("fft_planning", "measure", {"measure", "estimate"}) == "estimate" ? PlanRigor::Estimate
                                                                                                : PlanRigor::Measure;
  run.pipeline = build_pipeline(cfg);
  cfg.reject_unknown_keys();
  run.summary.scales = run.pipeline.ids();
  run.summary.parameters = cfg.to_json();
  run.fingerprint = case_fingerprint(run.summary.parameters);
  return run;
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
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
    j = nlohmann::json::parse(slurp(summary_file));
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
  run.summary.results = j.value("results", nlohmann::json::object());
  for (const auto& f : j.value("files", nlohmann::json::array())) run.summary.files.emplace_back(f.get<std::string>());
  run.complete = true;
}

void execute(PreparedRun& run, const RunOptions& options, bool show_progress) {
  RunSummary& summary = run.summary;
  if (run.complete) {
    log::info("{}: already complete", summary.output_dir.string());
    return;
  }
  std::error_code ec;
  std::filesystem::create_directories(summary.output_dir, ec);
  if (ec)
    throw InputError(fmt::format("output folder {}: cannot create it: {}", summary.output_dir.string(), ec.message()));
  remove_stale_partials(summary.output_dir);  // left by a killed run
  if (!run.checkpoints) run.checkpoints.emplace(summary.output_dir / "checkpoint.h5", run.fingerprint, run.policy);
  if (!run.resume) run.checkpoints->discard();  // a fresh run: an older checkpoint must not be resumed later
  H5Writer h5(summary.output_dir / "run.h5");
  h5.set_attribute("/", "case_file", options.case_file.string());
  h5.set_attribute("/", "case_toml", run.cfg.to_toml());
  h5.set_attribute("/", "wearscale_version", WEARSCALE_VERSION);
  h5.set_attribute("/", "created", utc_now());

  RunContext context(summary.output_dir, h5, show_progress, &*run.checkpoints);
  Exchange exchange;
  run.pipeline.run(exchange, context);

  nlohmann::json provenance = nlohmann::json::object();
  for (const auto& key : exchange.keys()) {
    const auto p = exchange.provenance(key).to_json();
    provenance[key.to_string()] = p;
    // One group per quantity, named by it, so the producer of each is visible in the file.
    std::string subject = key.subject;  // "SiO2/Si" would nest groups: store it as "SiO2-Si"
    std::replace(subject.begin(), subject.end(), '/', '-');
    const std::string group = "/exchange/" + to_string(key.what) + "/" + subject;
    h5.set_attribute(group, "producer", p["scale"].get<std::string>() + "/" + p["backend"].get<std::string>());
    h5.set_attribute(group, "provenance", p.dump());
  }
  h5.set_attribute("/", "provenance", provenance.dump(1));
  for (const auto& [name, r] : context.results().items()) {
    h5.write_scalar("/results/" + name, r["value"].get<double>(), r["unit"].get<std::string>());
    h5.set_attribute("/results/" + name, "description", r["description"].get<std::string>());
  }
  summary.results = context.results();
  summary.files = context.files();
  h5.commit();
  summary.files.insert(summary.files.begin(), h5.final_path());
  const auto friction = summary.output_dir / "friction.csv";
  if (std::filesystem::exists(friction))
    if (auto png = plot_friction_curves({{summary.case_name, friction}}, summary.output_dir / "friction.png",
                                        summary.case_name))
      summary.files.push_back(*png);
  write_file_atomically(summary.output_dir / "summary.json", summary.to_json().dump(2) + "\n");
  summary.files.push_back(summary.output_dir / "summary.json");
  if (run.checkpoints->saves() > 0)
    log::debug("{}: {} checkpoints written in {:.3f} s", summary.output_dir.string(), run.checkpoints->saves(),
               run.checkpoints->seconds_saving());
  run.checkpoints->discard();  // complete: nothing to resume
}

// How to continue an interrupted run, added to the Interrupted message.
[[noreturn]] void rethrow_interrupted(const Interrupted& e, const RunOptions& options,
                                      const std::filesystem::path& dir) {
  std::string sets;
  for (const auto& o : options.overrides) sets += fmt::format(" --set '{}'", o);
  throw Interrupted(fmt::format("{}; continue with: wearscale run {}{} --resume {}", e.what(),
                                options.case_file.string(), sets, dir.string()));
}

std::string label_of(const std::string& key, const std::string& value) {
  std::string leaf = key.substr(key.rfind('.') + 1) + "=" + value;
  for (auto& c : leaf)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '=' || c == '.' || c == '-' || c == '+' || c == '_'))
      c = '_';
  return leaf;
}

RunSummary run_sweep(const RunOptions& options, Config& probe) {
  const std::string key = probe.string("sweep.key");
  const auto values = probe.values_as_text("sweep.values");
  const std::string table_name = probe.string_or("sweep.table", "sweep.csv");
  const bool parallel = probe.boolean_or("sweep.parallel", true);
  // [sweep.series]: the sweep once more per value of a second key.
  const std::string series_key = probe.has("sweep.series") ? probe.string("sweep.series.key") : std::string();
  const auto series = series_key.empty() ? std::vector<std::string>{""} : probe.values_as_text("sweep.series.values");
  RunSummary sweep;
  sweep.case_name = probe.string("case.name");
  sweep.output_dir = options.output_dir ? *options.output_dir
                                        : std::filesystem::path(probe.string_or("output.dir", "out/" + sweep.case_name));
  sweep.sweep_key = key;
  sweep.series_key = series_key;

  // Every run is checked before any starts; resuming, every checkpoint is
  // read (and its FFT plans imported) before any run makes a plan.
  std::vector<PreparedRun> runs;
  std::vector<std::string> run_value, run_series;
  for (const auto& sv : series) {
    if (!series_key.empty() && !probe.has(series_key))
      throw probe.error("sweep.series.key", "the series key is not in the case (give it a value there first)",
                        "a key of the case");
    const auto folder = series_key.empty() ? sweep.output_dir : sweep.output_dir / label_of(series_key, sv);
    for (const auto& v : values) {
      if (!probe.has(key))
        throw probe.error("sweep.key", "the swept key is not in the case (give it a value there first)", "a key of the case");
      std::vector<std::string> extra{key + "=" + v};
      if (!series_key.empty()) extra.push_back(series_key + "=" + sv);
      runs.push_back(prepare(load(options, extra), folder / label_of(key, v)));
      run_value.push_back(v);
      run_series.push_back(sv);
    }
  }
  sweep.sweep_values = run_value;
  if (!series_key.empty()) sweep.series_values = run_series;
  if (options.resume_dir) {
    for (auto& r : runs) find_resume_point(r);
    const auto finished = std::count_if(runs.begin(), runs.end(), [](const PreparedRun& r) { return r.complete; });
    log::info("resuming the sweep in {}: {} of {} runs complete", sweep.output_dir.string(), finished, runs.size());
  }
  FFTPlanCache::global().set_rigor(runs.front().fft_rigor);
  sweep.scales = runs.front().summary.scales;
  sweep.parameters = runs.front().summary.parameters;
  sweep.parameters["sweep"] = {{"key", key}, {"values", values}};
  if (!series_key.empty()) sweep.parameters["sweep"]["series"] = {{"key", series_key}, {"values", series}};

  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const unsigned workers = parallel ? std::min<unsigned>(cores, static_cast<unsigned>(runs.size())) : 1u;
  log::info("sweep over {}: {} runs on {} worker(s) → {}", key, runs.size(), workers, sweep.output_dir.string());
  std::vector<std::exception_ptr> errors(runs.size());
  std::atomic<std::size_t> next{0}, done{0};
  std::mutex progress_mutex;
  Progress progress("sweep", static_cast<double>(runs.size()), "runs");
  auto work = [&] {
    if (workers > 1) omp_set_num_threads(1);  // the cores are shared out among runs
    for (std::size_t k = next++; k < runs.size() && !interrupt_requested(); k = next++) {
      try {
        execute(runs[k], options, false);
      } catch (...) {
        errors[k] = std::current_exception();
      }
      std::lock_guard lock(progress_mutex);
      progress.update(static_cast<double>(++done));
    }
  };
  std::vector<std::thread> pool;
  for (unsigned w = 1; w < workers; ++w) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  progress.finish();
  try {
    throw_if_interrupted("sweep");  // also when the signal came between runs
    for (auto& e : errors)
      if (e) std::rethrow_exception(e);
  } catch (const Interrupted& e) {
    rethrow_interrupted(e, options, sweep.output_dir);
  }

  // The sweep table (one per series value): the swept value, then every
  // headline figure of the runs.
  std::vector<std::string> names;
  for (const auto& r : runs)
    for (const auto& [name, v] : r.summary.results.items())
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  // A swept value that is not a number (a choice) is written as its index.
  bool numeric = true;
  for (const auto& v : values) {
    try {
      (void)units::parse_quantity(v);
    } catch (const std::exception&) {
      numeric = false;
    }
  }
  std::string legend;
  for (std::size_t k = 0; k < values.size() && !numeric; ++k) legend += fmt::format("{}{} = {}", k ? ", " : "", k, values[k]);
  std::vector<SweepTable> tables;
  for (std::size_t first = 0; first < runs.size(); first += values.size()) {
    std::vector<std::vector<double>> columns(names.size() + 1);
    for (std::size_t k = first; k < first + values.size(); ++k) {
      columns[0].push_back(numeric ? units::parse_quantity(run_value[k]).value : static_cast<double>(k - first));
      for (std::size_t c = 0; c < names.size(); ++c) {
        const auto& res = runs[k].summary.results;
        columns[c + 1].push_back(res.contains(names[c]) ? res[names[c]]["value"].get<double>() : std::nan(""));
      }
    }
    std::vector<std::string> header{key};
    header.insert(header.end(), names.begin(), names.end());
    std::vector<std::span<const double>> spans(columns.begin(), columns.end());
    const std::filesystem::path base(table_name);
    const std::string label = series_key.empty() ? "" : label_of(series_key, run_series[first]);
    const auto table = sweep.output_dir / (label.empty() ? base : std::filesystem::path(base.stem().string() + "_" + label +
                                                                                        base.extension().string()));
    std::vector<std::string> comments{
        fmt::format("sweep of case '{}' over {} (SI units; nan: not reached)", sweep.case_name, key)};
    if (!label.empty()) comments.push_back(fmt::format("series: {} = {}", series_key, run_series[first]));
    if (!numeric) comments.push_back(fmt::format("{}: the index of the value: {}", key, legend));
    write_csv(table, header, spans, comments);
    sweep.files.push_back(table);
    tables.push_back({label.empty() ? "model" : label, table});
  }

  std::vector<FrictionCurve> curves;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    sweep.runs.push_back(runs[k].summary);
    const auto csv = runs[k].summary.output_dir / "friction.csv";
    const std::string label = label_of(key, run_value[k]) + (series_key.empty() ? "" : " " + label_of(series_key, run_series[k]));
    if (std::filesystem::exists(csv)) curves.push_back({label, csv});
  }
  if (!curves.empty())
    if (auto png = plot_friction_curves(curves, sweep.output_dir / "friction_curves.png", sweep.case_name))
      sweep.files.push_back(*png);
  std::vector<FrictionCurve> profiles;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const auto csv = runs[k].summary.output_dir / "disc_profile.csv";
    if (std::filesystem::exists(csv)) profiles.push_back({curves.size() == runs.size() ? curves[k].label : csv.parent_path().filename().string(), csv});
  }
  if (!profiles.empty()) {
    const std::string thickness = "materials.layer.thickness";  // one oxide for all runs: its interface is drawn
    const bool one_oxide = key != thickness && series_key != thickness && probe.has(thickness);
    const double h = one_oxide ? probe.number(thickness, Range::non_negative().or_infinite(), units::length) : 0.0;
    if (auto png = plot_disc_profiles(profiles, sweep.output_dir / "disc_profiles.png", sweep.case_name, h))
      sweep.files.push_back(*png);
  }
  if (key == "materials.layer.thickness" && std::find(names.begin(), names.end(), "mu_mean") != names.end())
    if (auto png = plot_friction_vs_thickness(tables, sweep.output_dir / "friction_vs_thickness.png"))
      sweep.files.push_back(*png);
  write_file_atomically(sweep.output_dir / "summary.json", sweep.to_json().dump(2) + "\n");
  sweep.files.push_back(sweep.output_dir / "summary.json");
  return sweep;
}

}  // namespace

RunSummary run_case(const RunOptions& options_in) {
  RunOptions options = options_in;
  if (options.resume_dir)
    options.output_dir = resume_folder(*options.resume_dir, options.output_dir.value_or(std::filesystem::path()));
  Config probe = load(options, {});
  if (probe.has("sweep")) return run_sweep(options, probe);
  PreparedRun run = prepare(std::move(probe), options.output_dir);  // a single run: the file is parsed once
  if (options.resume_dir) find_resume_point(run);
  FFTPlanCache::global().set_rigor(run.fft_rigor);
  log::info("case '{}': {} → {}", run.summary.case_name, fmt::join(run.summary.scales, " → "),
            run.summary.output_dir.string());
  try {
    execute(run, options, true);
  } catch (const Interrupted& e) {
    rethrow_interrupted(e, options, run.summary.output_dir);
  }
  return run.summary;
}

}  // namespace wearscale::coupling
