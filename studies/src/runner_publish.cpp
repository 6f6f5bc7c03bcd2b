#include "runner_publish.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <span>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "wearscale/core/log.hpp"
#include "wearscale/core/output_set.hpp"
#include "wearscale/core/units.hpp"
#include "wearscale/io/csv.hpp"

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

namespace runner {
namespace {

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

// The columns of a sweep table after the swept value: every headline figure
// of the runs, in the order first met, with its unit (SI, or "1" for one
// without: a count, a ratio), then `failed` when a run failed.
struct ResultColumns {
  std::vector<std::string> names, units;
};

ResultColumns result_columns(const std::vector<PreparedRun>& runs, bool any_failed) {
  ResultColumns columns;
  for (const auto& r : runs)
    for (const auto& [name, v] : r.summary.results.items())
      if (std::find(columns.names.begin(), columns.names.end(), name) == columns.names.end()) {
        columns.names.push_back(name);
        const std::string unit = v.contains("unit") ? v["unit"].get<std::string>() : "";
        columns.units.push_back(unit.empty() ? "1" : unit);
      }
  if (any_failed) {
    columns.names.push_back("failed");
    columns.units.push_back("1");
  }
  return columns;
}

// The swept values as numbers in SI, in the dimension the case reads the key
// in (a bare number is SI in it: a thickness of 1e-6 is metres); `all` false
// when one is not a number (the tables then keep the values as written).
struct SweptNumbers {
  std::vector<double> values;
  std::optional<units::Dimension> dimension;
  bool all = false;
};

SweptNumbers swept_numbers(const SweepPlan& plan) {
  const std::vector<PreparedRun>& runs = plan.runs;
  const std::string& key = plan.sweep.sweep_key;
  SweptNumbers swept;
  std::vector<double>& numeric = swept.values;
  std::optional<units::Dimension>& swept_dimension = swept.dimension;
  swept_dimension = runs.front().cfg.dimension_of(key);
  if (swept_dimension) {
    for (std::size_t k = 0; k < plan.values.size(); ++k) try {
        numeric.push_back(runs[k].cfg.number(key, Range::any().or_infinite(), *swept_dimension));
      } catch (const std::exception&) {
        numeric.clear();
        break;
      }
  } else {  // a key no number getter read (an integer, a choice): its values as written
    for (const auto& v : plan.values) try {
        const auto q = units::parse_quantity(v);
        if (swept_dimension && !(*swept_dimension == q.dimension)) throw std::invalid_argument("mixed dimensions");
        swept_dimension = q.dimension;
        numeric.push_back(q.value);
      } catch (const std::exception&) {
        numeric.clear();
        break;
      }
  }
  swept.all = numeric.size() == plan.values.size();
  return swept;
}

// One sweep table per series value (its runs follow one another in the
// plan), each added to the sweep's files; returns each table's label
// ("model" without a series) and file.
std::vector<std::pair<std::string, std::filesystem::path>> write_sweep_tables(
    SweepPlan& plan, const ResultColumns& results, const SweptNumbers& swept,
    const std::vector<std::string>& failures, bool any_failed) {
  RunSummary& sweep = plan.sweep;
  const std::vector<PreparedRun>& runs = plan.runs;
  const std::string& key = sweep.sweep_key;
  const std::vector<std::string>& values = plan.values;
  const std::vector<std::string>& names = results.names;
  const std::string& series_key = plan.series_key;
  const std::string column = swept_column(key);
  std::vector<std::pair<std::string, std::filesystem::path>> tables;
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
    if (swept.all) spans.emplace_back(swept.values);
    for (const auto& c : columns) spans.emplace_back(c);
    const std::filesystem::path base(plan.table_name);
    const std::string label = series_key.empty() ? "" : label_of(series_key, plan.run_series[first]);
    const auto table = sweep.output_dir / (label.empty() ? base : std::filesystem::path(base.stem().string() + "_" + label +
                                                                                        base.extension().string()));
    std::vector<std::string> comments{
        fmt::format("sweep of case '{}' over {} (column {}); SI units unless a column's name says otherwise; nan: "
                    "not reached",
                    sweep.case_name, key, swept.all ? csv_column_name(column, swept.dimension->to_string()) : column)};
    if (!label.empty()) comments.push_back(fmt::format("series: {} = {}", series_key, plan.run_series[first]));
    if (any_failed) comments.push_back("failed = 1: the run failed (summary.json lists why); its figures are nan");
    if (swept.all) {
      std::vector<std::string> header{column}, header_units{swept.dimension->to_string()};
      header.insert(header.end(), names.begin(), names.end());
      header_units.insert(header_units.end(), results.units.begin(), results.units.end());
      write_csv(table, header, spans, header_units, comments);
    } else {
      write_csv(table, column, values, names, spans, results.units, comments);
    }
    sweep.files.push_back(table);
    tables.push_back({label.empty() ? "model" : label, table});
  }
  return tables;
}

// What the study's finish_sweep is given: the swept keys, the tables, and each run's folder, label and values.
Study::SweepRuns sweep_runs_view(const SweepPlan& plan, const Config& probe, const ResultColumns& results,
                                 bool numeric_values,
                                 const std::vector<std::pair<std::string, std::filesystem::path>>& tables) {
  const RunSummary& sweep = plan.sweep;
  const std::string& key = sweep.sweep_key;
  const std::string& series_key = plan.series_key;
  Study::SweepRuns view;
  view.probe = &probe;
  view.key = key;
  view.series_key = series_key;
  view.numeric_values = numeric_values;
  view.result_names = results.names;
  view.case_name = sweep.case_name;
  view.output_dir = sweep.output_dir;
  for (const auto& t : tables) view.tables.emplace_back(t.first, t.second);
  for (std::size_t k = 0; k < plan.runs.size(); ++k) {
    const std::string& value = sweep.sweep_values[k];
    const std::string& series = plan.run_series[k];
    view.folders.push_back(plan.runs[k].summary.output_dir);
    view.labels.push_back(label_of(key, value) + (series_key.empty() ? "" : " " + label_of(series_key, series)));
    view.values.push_back(value);
    view.series_values.push_back(series_key.empty() ? std::string() : series);
  }
  return view;
}

}  // namespace

void publish_sweep(SweepPlan& plan, Config& probe, const std::vector<std::string>& failures,
                   const nlohmann::json& tasks) {
  RunSummary& sweep = plan.sweep;
  const std::vector<PreparedRun>& runs = plan.runs;
  const bool any_failed = std::any_of(failures.begin(), failures.end(), [](const std::string& f) { return !f.empty(); });
  OutputSet outputs(sweep.output_dir, "summary.json");
  for (const auto& folder : run_folders_of(plan)) outputs.own_folder(folder);  // the sweep's runs: its set
  const ResultColumns results = result_columns(runs, any_failed);
  const SweptNumbers swept = swept_numbers(plan);
  const auto tables = write_sweep_tables(plan, results, swept, failures, any_failed);
  for (const auto& run : runs) sweep.runs.push_back(run.summary);
  if (any_failed)
    log::warn("{}: no sweep plots (some runs failed)", sweep.output_dir.string());
  else
    for (auto& f : runs.front().study->finish_sweep(sweep_runs_view(plan, probe, results, swept.all, tables)))
      sweep.files.push_back(std::move(f));
  sweep.files.push_back(sweep.output_dir / "summary.json");
  nlohmann::json summary = sweep.to_json();
  if (!tasks.is_null()) summary["tasks"] = tasks;
  if (any_failed) {
    summary["failed"] = nlohmann::json::array();
    for (std::size_t k = 0; k < runs.size(); ++k)
      if (!failures[k].empty())
        summary["failed"].push_back({{"run", k + 1}, {"value", sweep.sweep_values[k]},
                                     {"output_dir", runs[k].summary.output_dir.string()}, {"error", failures[k]}});
  }
  outputs.commit(summary);
}

}  // namespace runner
}  // namespace wearscale::studies
