// wearscale check CASE.toml [--set KEY=VALUE]... [--out DIR] [--json]
// Checks a case as `wearscale run` reads it (every key, every independent
// error at once) and prints it resolved, with every default and the memory it
// needs; runs and writes nothing. Exit 0 valid, 2 invalid.
#include "commands.hpp"
#include "study_command.hpp"

namespace wearscale::app {

Command add_check(CLI::App& app) {
  auto* cmd = app.add_subcommand("check", "Check a case file without running it: every key and every error at once; "
                                          "print the resolved case with every default and the memory it needs; "
                                          "nothing is written");
  auto f = std::make_shared<StudyFlags>();
  cmd->add_option("case", f->options.case_file, "Case file (TOML), e.g. cases/pin_on_disc_si_oxide.toml")->required();
  cmd->add_option("--set", f->options.overrides, "Override a case key, as `wearscale run` takes it (repeatable)")
      ->take_all()
      ->expected(1)
      ->allow_extra_args(false);
  cmd->add_option("--out", f->out, "The output folder the run would write (checked, not created)");
  cmd->add_flag("--json", f->json, "Print one JSON object: the resolved case, its defaults, the memory");
  return [f]() { return check_study(*f); };
}

}  // namespace wearscale::app
