// wearscale run CASE.toml [--set KEY=VALUE]... [--out DIR] [--resume DIR] [--json]
// Runs any study a case file names (studies/study.hpp: study_of).
#include <iostream>

#include <fmt/format.h>

#include "commands.hpp"
#include "study_command.hpp"

namespace wearscale::app {

void print_results(const nlohmann::json& results) {
  for (const auto& [name, r] : results.items())
    std::cout << fmt::format("{:<22} {:>14.6g} {:<4} {}\n", name, r["value"].get<double>(),
                             r["unit"].get<std::string>(), r["description"].get<std::string>());
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

Command add_run(CLI::App& app) {
  auto* cmd = app.add_subcommand("run", "Run a case file: its study (the scale pipeline, contact, ...), its sweep, its outputs");
  auto f = std::make_shared<StudyFlags>();
  cmd->add_option("case", f->options.case_file, "Case file (TOML), e.g. cases/pin_on_disc_si_oxide.toml")->required();
  add_runner_flags(cmd, *f, "scale.macro.grid=64");
  return [f]() { return run_study(*f); };
}

}  // namespace wearscale::app
