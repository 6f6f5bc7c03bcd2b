#include "runner_sweep_plan.hpp"

#include "wearscale/studies/runner_keys.hpp"

#include <algorithm>
#include <cctype>
#include <exception>
#include <map>
#include <optional>

#include <fmt/format.h>

#include "wearscale/core/interrupt.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/core/units.hpp"

namespace wearscale::studies::runner {

std::string label_of(const std::string& key, const std::string& value) {
  std::string leaf = key.substr(key.rfind('.') + 1) + "=" + value;
  for (auto& c : leaf)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '=' || c == '.' || c == '-' || c == '+' || c == '_'))
      c = '_';
  return leaf;
}

namespace {

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
    const auto look = [&](auto& seen, const auto& entry) {
      const auto [it, inserted] = seen.emplace(entry, a);
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

}  // namespace

SweepPlan plan_sweep(const CaseLoader& parse, const RunOptions& options, Config& probe) {
  SweepPlan plan;
  SweepKeys given;
  sweep_keys().read(probe.section("sweep"), given);
  probe.section("sweep").reject_unknown_keys();  // a misspelt [sweep] key is no silent default
  const std::string key = given.key;
  const auto values = given.values;
  plan.table_name = given.table;
  plan.parallel = given.parallel;
  // [sweep.series]: the sweep once more per value of a second key.
  plan.series_key = given.series_key;
  plan.series = plan.series_key.empty() ? std::vector<std::string>{""} : given.series_values;
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
    CaseKeys names;
    names.default_name = study->default_case_name();
    names.default_dir = study->default_output_dir();
    case_keys().read(probe, names);
    sweep.case_name = names.name;
    sweep.output_dir = options.output_dir ? *options.output_dir : std::filesystem::path(names.output_dir);
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

void describe_sweep(SweepPlan& plan, const RunOptions& options) {
  RunSummary& sweep = plan.sweep;
  sweep.scales = plan.runs.front().summary.scales;
  sweep.provenance = provenance_of(sweep, options);
  sweep.parameters = plan.runs.front().summary.parameters;
  sweep.parameters["sweep"] = {{"key", sweep.sweep_key}, {"values", plan.values}};
  if (!plan.series_key.empty())
    sweep.parameters["sweep"]["series"] = {{"key", plan.series_key}, {"values", plan.series}};
}

std::vector<std::filesystem::path> run_folders_of(const SweepPlan& plan) {
  std::vector<std::filesystem::path> out;
  for (const auto& r : plan.runs) out.push_back(r.summary.output_dir.lexically_relative(plan.sweep.output_dir));
  return out;
}

}  // namespace wearscale::studies::runner
