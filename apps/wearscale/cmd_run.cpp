// wearscale run CASE.toml [--set KEY=VALUE]... [--out DIR] [--json]
#include <iostream>

#include <fmt/format.h>

#include "commands.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/coupling/case_runner.hpp"

namespace wearscale::app {

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
  cmd->add_flag("--json", *json, "Print one JSON object with the headline results and resolved parameters");
  return [options, json, out]() {
    if (!out->empty()) options->output_dir = *out;
    const auto summary = coupling::run_case(*options);
    if (*json) {
      std::cout << summary.to_json().dump(2) << '\n';
      return 0;
    }
    for (const auto& [name, r] : summary.results.items())
      std::cout << fmt::format("{:<22} {:>14.6g} {:<4} {}\n", name, r["value"].get<double>(),
                               r["unit"].get<std::string>(), r["description"].get<std::string>());
    for (const auto& f : summary.files) log::info("wrote {}", f.string());
    return 0;
  };
}

}  // namespace wearscale::app
