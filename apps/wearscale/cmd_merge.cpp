// wearscale merge DIR [--json]: the sweep table and summary of an ensemble
// whose shards (--task K/N) ran into DIR (studies::merge_shards).
#include "commands.hpp"
#include "study_command.hpp"
#include "wearscale/studies/runner.hpp"

namespace wearscale::app {

Command add_merge(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "merge", "Write the outputs of an ensemble whose shards (--task K/N) ran into DIR, once all are done: a "
               "sweep's table and summary, or the run whose ensembles' tasks the shards kept (refused, naming the "
               "tasks, while some are not)");
  auto dir = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  cmd->add_option("dir", *dir, "The output folder the shards share")->required()->type_name("DIR");
  cmd->add_flag("--json", *json, "Print one JSON object: the summary");
  return [dir, json]() {
    print_summary(studies::merge_shards(*dir, invocation()), *json);
    return 0;
  };
}

}  // namespace wearscale::app
