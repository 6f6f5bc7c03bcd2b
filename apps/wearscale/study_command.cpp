#include "study_command.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>
#include <string_view>

#include <fmt/format.h>

#include "completion.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/io/shipped_data.hpp"
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

// "MIN:MAX" → "[MIN, MAX]"; InputError naming the flag otherwise.
std::string range_to_toml(const std::string& flag, const std::string& text) {
  const auto bad = [&]() {
    return InputError(fmt::format("{} = '{}' is not a range; allowed: MIN:MAX, e.g. 0.01:0.3", flag, text));
  };
  const auto colon = text.find(':');
  if (colon == std::string::npos) throw bad();
  auto number = [&](std::string_view s) {
    double v = 0.0;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(v)) throw bad();
    return v;
  };
  const std::string_view all(text);
  return fmt::format("[{}, {}]", number(all.substr(0, colon)), number(all.substr(colon + 1)));
}

// "0,10,25" with unit "GPa" → ["0 GPa", "10 GPa", "25 GPa"]; InputError naming the flag for an item that is
// not a plain number.
std::string list_to_toml(const std::string& flag, const std::string& list, const std::string& unit,
                         const std::string& key) {
  std::string out;
  for (std::size_t start = 0;;) {
    const auto comma = list.find(',', start);
    std::string item = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const auto b = item.find_first_not_of(" \t"), e = item.find_last_not_of(" \t");
    item = b == std::string::npos ? std::string() : item.substr(b, e - b + 1);
    double v = 0.0;
    const auto [ptr, ec] = std::from_chars(item.data(), item.data() + item.size(), v);
    if (item.empty() || ec != std::errc() || ptr != item.data() + item.size())
      throw InputError(fmt::format("{} '{}': '{}' is not a number; {} takes plain numbers in {} separated by commas, "
                                   "e.g. {} 0,10,25 (unit strings go in the case key: --set '{}=[\"0 {}\", \"10 {}\"]')",
                                   flag, list, item, flag, unit, flag, key, unit, unit));
    out += fmt::format("{}\"{} {}\"", out.empty() ? "" : ", ", item, unit);
    if (comma == std::string::npos) return "[" + out + "]";
    start = comma + 1;
  }
}

// One row per swept value: the headline figures of the pin-on-disc runs when
// present, else every figure.
void print_sweep_table(const studies::RunSummary& summary) {
  const std::vector<std::string> preferred = {"mu_mean", "mu_final", "pin_wear", "disc_wear", "substrate_reached_at",
                                              "grooves"};
  std::vector<std::string> columns;
  if (summary.runs.empty()) return;  // a shard with no run of its own (more shards than runs)
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
  cmd->add_option("--out", f.out, "Output folder (default: [output].dir of the case, else out/<case name>)")
      ->each([&f](const std::string&) { f.out_given = true; });
  cmd->add_option("--resume", f.resume,
                  "Continue the killed or interrupted run whose output folder is DIR from its checkpoint (same case "
                  "and --set options; a sweep reruns only its unfinished runs, a run's ensembles only their "
                  "unfinished tasks, under any number of MPI ranks)")
      ->type_name("DIR")
      ->each([&f](const std::string&) { f.resume_given = true; });
  cmd->add_option("--task", f.task,
                  "Run only the K-th of N shards of the case's ensemble (the runs of its [sweep], else the tasks "
                  "of the run's ensembles: a wear map's surfaces, junction runs, LAMMPS points; those k with "
                  "k mod N = K-1) into the output folder, which the other shards share (a job array); `wearscale "
                  "merge DIR` writes the outputs once all are done")
      ->type_name("K/N")
      ->each([&f](const std::string&) { f.task_given = true; });
  cmd->add_flag("--json", f.json, "Print one JSON object with the headline results and resolved parameters");
  cmd->add_flag("--dry-run", f.dry_run,
                "Check the case (every key, every error at once) and print it resolved, with every default and the "
                "memory it needs; run nothing, write nothing (as `wearscale check`)");
}

void add_schema_flags(CLI::App* cmd, StudyFlags& f, const std::string& study) {
  for (const auto& spec : studies::study_registry().create(study)->schema())
    if (spec.flag.empty()) continue;
    else if (spec.switch_value.empty()) {
      auto& given = f.keys[spec.key];
      given.flag = spec.flag;
      given.range = spec.type == "range";
      given.list_unit = spec.list_unit;
      // A flag without dashes ("file") is the command's positional argument.
      auto* option = cmd->add_option(spec.flag, given.value, studies::help_line(spec));
      if (spec.type == "choice") with_choices(option, choice_list(spec.range));
      if (given.range) option->type_name("MIN:MAX");
    }
    else {  // a switch: sets its key to one value
      f.keys[spec.key] = {spec.flag, "", false, true, ""};
      cmd->add_flag_callback(spec.flag, [&f, spec] { f.keys[spec.key].value = spec.switch_value; },
                             fmt::format("{} = {}: {}", spec.key, spec.switch_value, spec.doc));
    }
}

namespace {
// A case named as the help's examples name it (cases/hertz_pin.toml) that is not in the working
// folder: the example case that `cmake --install` put under share/wearscale, so that the examples
// run from an installed tree as they do from the source tree.
void find_installed_case(studies::RunOptions& options) {
  std::error_code ec;
  if (options.case_file.empty() || options.case_file.is_absolute() || std::filesystem::exists(options.case_file, ec))
    return;
  const auto installed = materials::installed_file(options.case_file);
  if (installed.empty()) return;
  log::info("{} is not in the working folder: reading the installed example {}", options.case_file.string(),
            installed.string());
  options.case_file = installed;
}

// The alias flags (then --set), --out and --resume into the runner's options.
void resolve_flags(StudyFlags& f) {
  find_installed_case(f.options);
  for (const auto& [key, given] : f.keys)
    if (!given.value.empty())
      f.options.flags.emplace_back(
          key + "=" + (given.range                ? range_to_toml(given.flag, given.value)
                       : !given.list_unit.empty() ? list_to_toml(given.flag, given.value, given.list_unit, key)
                                                  : given.value),
          given.is_switch ? given.flag : given.flag + " " + given.value);
  // Given, even empty: the runner refuses an empty --out rather than take the default folder.
  if (f.out_given) f.options.output_dir = f.out;
  if (f.resume_given) f.options.resume_dir = f.resume;
  if (f.task_given) f.options.task = f.task;
}
}  // namespace

int check_study(StudyFlags& f) {
  resolve_flags(f);
  if (f.options.resume_dir || f.options.task)
    throw InputError("--dry-run checks a case as a fresh run does; drop --resume and --task");
  const auto report = studies::inspect_case(studies::case_loader(f.options), f.options);
  if (!mpi::is_root()) return 0;
  std::cout << (f.json ? report.to_json().dump(2) + "\n" : report.text());
  return 0;
}

int run_study(StudyFlags& f) {
  if (f.dry_run) return check_study(f);
  resolve_flags(f);
  const auto summary = studies::run_case(f.options);
  if (!mpi::is_root()) return 0;  // under mpirun rank 0 prints the job's summary
  print_summary(summary, f.json);
  return 0;
}

void print_summary(const studies::RunSummary& summary, bool json) {
  if (json) {
    std::cout << summary.to_json().dump(2) << '\n';
    return;
  }
  if (summary.sweep_key.empty())
    print_results(summary.results);
  else
    print_sweep_table(summary);
  // A resumed run that had completed wrote nothing: its files are kept as they were.
  for (const auto& file : summary.files) log::info("{} {}", summary.complete_before ? "kept" : "wrote", file.string());
}

Command add_study_command(CLI::App& app, const std::string& command, const std::string& study,
                          const std::string& description, const std::string& set_example) {
  auto* cmd = app.add_subcommand(command, description);
  auto f = std::make_shared<StudyFlags>();
  f->options.study = study;
  // The case file is the positional argument, unless a key of the study is (`surface analyze FILE`).
  const auto schema = studies::study_registry().create(study)->schema();
  if (std::none_of(schema.begin(), schema.end(), [](const auto& k) { return !k.flag.empty() && k.flag[0] != '-'; }))
    cmd->add_option("case", f->options.case_file, "Case file (TOML); without one the flags and --set give the keys");
  add_schema_flags(cmd, *f, study);
  add_runner_flags(cmd, *f, set_example);
  return [f]() {
    f->options.command = invocation();
    return run_study(*f);
  };
}

}  // namespace wearscale::app
