// wearscale run CASE.toml [--set KEY=VALUE]... [--out DIR] [--resume DIR] [--json]
#include <algorithm>
#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "commands.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/coupling/case_runner.hpp"

namespace wearscale::app {

void print_results(const nlohmann::json& results) {
  for (const auto& [name, r] : results.items())
    std::cout << fmt::format("{:<22} {:>14.6g} {:<4} {}\n", name, r["value"].get<double>(),
                             r["unit"].get<std::string>(), r["description"].get<std::string>());
}

void require_finite_results(const nlohmann::json& results, const std::string& solver) {
  for (const auto& [name, r] : results.items()) {
    const auto& v = r.contains("value") ? r["value"] : r;
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      throw NumericalError(solver, 0, name, fmt::format("the result is {} (NaN or infinite)", v.dump()));
  }
}

namespace {
std::string& invocation_text() {
  static std::string text = "wearscale";
  return text;
}
}  // namespace

const std::string& invocation() { return invocation_text(); }

void set_invocation(int argc, char** argv) {
  std::string line = "wearscale";
  for (int k = 1; k < argc; ++k) line += std::string(" ") + argv[k];
  for (auto& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  invocation_text() = line;
}

namespace {
// One row per swept value: the headline figures of the pin-on-disc runs when
// present, else every figure.
void print_sweep_table(const coupling::RunSummary& summary) {
  const std::vector<std::string> preferred = {"mu_mean", "mu_final", "pin_wear", "disc_wear", "substrate_reached_at",
                                              "grooves"};
  std::vector<std::string> columns;
  const auto& first = summary.runs.front().results;
  for (const auto& c : preferred)
    for (const auto& r : summary.runs)
      if (r.results.contains(c) && std::find(columns.begin(), columns.end(), c) == columns.end()) columns.push_back(c);
  if (columns.empty())
    for (const auto& [name, v] : first.items()) columns.push_back(name);
  const bool series = !summary.series_key.empty();
  std::cout << fmt::format("{:<28}", summary.sweep_key);
  if (series) std::cout << fmt::format(" {:<28}", summary.series_key);
  for (const auto& c : columns) std::cout << fmt::format(" {:>20}", c);
  std::cout << '\n';
  for (std::size_t k = 0; k < summary.runs.size(); ++k) {
    std::cout << fmt::format("{:<28}", summary.sweep_values[k]);
    if (series) std::cout << fmt::format(" {:<28}", summary.series_values[k]);
    for (const auto& c : columns) {
      const auto& res = summary.runs[k].results;
      std::cout << (res.contains(c) ? fmt::format(" {:>20.6g}", res[c]["value"].get<double>()) : fmt::format(" {:>20}", "-"));
    }
    std::cout << '\n';
  }
}
}  // namespace

Command add_run(CLI::App& app) {
  auto* cmd = app.add_subcommand("run", "Run a case file: its scales in order, its sweep, its outputs");
  auto options = std::make_shared<coupling::RunOptions>();
  auto json = std::make_shared<bool>(false);
  auto out = std::make_shared<std::string>();
  cmd->add_option("case", options->case_file, "Case file (TOML), e.g. cases/pin_on_disc.toml")->required();
  cmd->add_option("--set", options->overrides, "Override a case key: --set scale.macro.grid=64 (repeatable)")
      ->take_all()
      ->expected(1)
      ->allow_extra_args(false);
  cmd->add_option("--out", *out, "Output folder (default: [output].dir of the case, else out/<case name>)");
  auto resume = std::make_shared<std::string>();
  cmd->add_option("--resume", *resume,
                  "Continue the killed or interrupted run whose output folder is DIR from its checkpoint (same case "
                  "and --set options; a sweep reruns only its unfinished runs)")
      ->type_name("DIR");
  cmd->add_flag("--json", *json, "Print one JSON object with the headline results and resolved parameters");
  return [options, json, out, resume]() {
    if (!out->empty()) options->output_dir = *out;
    if (!resume->empty()) options->resume_dir = *resume;
    const auto summary = coupling::run_case(*options);
    if (*json) {
      std::cout << summary.to_json().dump(2) << '\n';
      return 0;
    }
    if (summary.sweep_key.empty()) {
      print_results(summary.results);
    } else {
      print_sweep_table(summary);
    }
    // A resumed run that had completed wrote nothing: its files are kept as they were.
    for (const auto& f : summary.files) log::info("{} {}", summary.complete_before ? "kept" : "wrote", f.string());
    return 0;
  };
}

}  // namespace wearscale::app
