#include "study_command.hpp"

#include <algorithm>
#include <iostream>

#include <fmt/format.h>

#include "completion.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/studies/study.hpp"

namespace wearscale::app {

namespace {
// "hcp | amorphous" → {"hcp", "amorphous"}
std::vector<std::string> choice_list(const std::string& range) {
  std::vector<std::string> out;
  for (std::size_t start = 0;;) {
    const auto bar = range.find(" | ", start);
    out.push_back(range.substr(start, bar == std::string::npos ? std::string::npos : bar - start));
    if (bar == std::string::npos) return out;
    start = bar + 3;
  }
}

// One row per swept value: the headline figures of the pin-on-disc runs when
// present, else every figure.
void print_sweep_table(const studies::RunSummary& summary) {
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

void add_runner_flags(CLI::App* cmd, StudyFlags& f, const std::string& example) {
  cmd->add_option("--set", f.options.overrides, "Override a case key: --set " + example + " (repeatable)")
      ->take_all()
      ->expected(1)
      ->allow_extra_args(false);
  cmd->add_option("--out", f.out, "Output folder (default: [output].dir of the case, else out/<case name>)");
  cmd->add_option("--resume", f.resume,
                  "Continue the killed or interrupted run whose output folder is DIR from its checkpoint (same case "
                  "and --set options; a sweep reruns only its unfinished runs)")
      ->type_name("DIR");
  cmd->add_flag("--json", f.json, "Print one JSON object with the headline results and resolved parameters");
}

void add_schema_flags(CLI::App* cmd, StudyFlags& f, const std::string& study) {
  for (const auto& spec : studies::study_registry().create(study)->schema())
    if (spec.flag.empty()) continue;
    else if (spec.switch_value.empty()) {
      auto* option = cmd->add_option(spec.flag, f.keys[spec.key], studies::help_line(spec));
      if (spec.type == "choice") with_choices(option, choice_list(spec.range));
    }
    else  // a switch: sets its key to one value
      cmd->add_flag_callback(spec.flag, [&f, spec] { f.keys[spec.key] = spec.switch_value; },
                             fmt::format("{} = {}: {}", spec.key, spec.switch_value, spec.doc));
}

int run_study(StudyFlags& f) {
  std::vector<std::string> flags;  // the alias flags first, then --set
  for (const auto& [key, value] : f.keys)
    if (!value.empty()) flags.push_back(key + "=" + value);
  f.options.overrides.insert(f.options.overrides.begin(), flags.begin(), flags.end());
  if (!f.out.empty()) f.options.output_dir = f.out;
  if (!f.resume.empty()) f.options.resume_dir = f.resume;
  const auto summary = studies::run_case(f.options);
  if (!mpi::is_root()) return 0;  // under mpirun rank 0 prints the job's summary
  if (f.json) {
    std::cout << summary.to_json().dump(2) << '\n';
    return 0;
  }
  if (summary.sweep_key.empty())
    print_results(summary.results);
  else
    print_sweep_table(summary);
  // A resumed run that had completed wrote nothing: its files are kept as they were.
  for (const auto& file : summary.files) log::info("{} {}", summary.complete_before ? "kept" : "wrote", file.string());
  return 0;
}

Command add_study_command(CLI::App& app, const std::string& command, const std::string& study,
                          const std::string& description, const std::string& set_example) {
  auto* cmd = app.add_subcommand(command, description);
  auto f = std::make_shared<StudyFlags>();
  f->options.study = study;
  cmd->add_option("case", f->options.case_file, "Case file (TOML); without one the flags and --set give the keys");
  add_schema_flags(cmd, *f, study);
  add_runner_flags(cmd, *f, set_example);
  return [f]() {
    f->options.command = invocation();
    return run_study(*f);
  };
}

}  // namespace wearscale::app
