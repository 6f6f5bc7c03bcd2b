#pragma once
// What every study command shares: the runner's flags (--set, --out,
// --resume, --json), the alias flags that a study's schema declares, and
// printing a run's summary.
#include <map>
#include <memory>
#include <string>

#include "commands.hpp"
#include "wearscale/studies/runner.hpp"
#include "wearscale/studies/study.hpp"

namespace wearscale::app {

struct StudyFlags {
  /// What an alias flag gave its key.
  struct Given {
    std::string flag;   ///< "--hurst"
    std::string value;  ///< the text given; empty: not given
    bool range = false; ///< "MIN:MAX", written to the key as [MIN, MAX]
    bool is_switch = false;
    std::string list_unit;  ///< "A,B": plain numbers in this unit, written as ["A unit", "B unit"]
  };
  studies::RunOptions options;
  std::string out, resume, task;
  bool out_given = false, resume_given = false, task_given = false;  ///< given, even as an empty text
  bool json = false;
  bool dry_run = false;  ///< --dry-run: check and print the resolved case, as `wearscale check`
  std::map<std::string, Given> keys;  ///< schema key → its alias flag and value
};

/// Adds --set, --out, --resume, --task and --json to `cmd`; `example` is a key for --set's help.
void add_runner_flags(CLI::App* cmd, StudyFlags& flags, const std::string& example);
/// Adds the command-line alias of every key of `study`'s schema that has one.
void add_schema_flags(CLI::App* cmd, StudyFlags& flags, const std::string& study);
/// Runs the study through the runner and prints its summary (JSON with --json);
/// with --dry-run checks it instead (check_study).
int run_study(StudyFlags& flags);
/// Checks the case as the runner reads it, every error at once, and prints
/// the resolved case with every default and the memory it needs (JSON with
/// --json); runs and writes nothing. 0 when valid (InputError otherwise).
int check_study(StudyFlags& flags);
/// Prints a summary as run_study does (JSON with `json`).
void print_summary(const studies::RunSummary& summary, bool json);

/// A command that runs `study`: an optional case file (the positional
/// argument, unless a key's alias is: a flag without dashes), the schema's
/// alias flags, and the runner's flags.
/// (The subcommand is app.get_subcommands({}).back(), for extra checks such as excludes.)
Command add_study_command(CLI::App& app, const std::string& command, const std::string& study,
                          const std::string& description, const std::string& set_example);

}  // namespace wearscale::app
