// wearscale wearmap analytic2d [CASE.toml] [--dr-over-dstar MIN:MAX] [--da-over-dstar MIN:MAX] [--n N]
//                              [--set KEY=VALUE]... [--out DIR] [--resume DIR] [--json]
// wearscale wearmap analytic3d [CASE.toml] [--d-over-l MIN:MAX] [--dstar-over-l MIN:MAX] [--n N]
//                              [--interaction max|min | --nu NU --theta RAD] [--set KEY=VALUE]... [--out DIR] [--json]
// wearscale wearmap rough      [CASE.toml] [--n N] [--seeds S] [--hurst H] [--ql QL] [--qs QS] [--loads MIN:MAX] ...
// The wear-map studies of studies/src/wearmap_*_study.cpp (thesis ch. 3-5);
// each subcommand's flags are the aliases its schema declares.
#include <vector>

#include "study_command.hpp"

namespace wearscale::app {

Command add_wearmap(CLI::App& app) {
  auto* wearmap = app.add_subcommand("wearmap", "Wear maps of sheared micro-contacts (thesis ch. 3–5): which particles "
                                                "can detach, as regions of an energy ratio R ≥ 1");
  wearmap->require_subcommand(1);
  struct Entry {
    const char *command, *study, *set_example;  // a key of the study's own for --set's help
  };
  const Entry studies[] = {{"analytic2d", "wearmap/analytic2d", "wearmap.analytic2d.n=64"},
                           {"analytic3d", "wearmap/analytic3d", "wearmap.analytic3d.n=64"},
                           {"rough", "wearmap/rough", "wearmap.rough.seeds=2"}};
  std::vector<std::pair<CLI::App*, Command>> commands;
  for (const auto& [command, study, set_example] : studies) {
    auto run = add_study_command(*wearmap, command, study, studies::study_registry().create(study)->summary(),
                                 set_example);
    commands.emplace_back(wearmap->get_subcommands({}).back(), std::move(run));
  }
  // Fig. 4.6's interaction fixes ν and θ.
  auto* three = wearmap->get_subcommand("analytic3d");
  three->get_option("--interaction")->excludes(three->get_option("--nu"))->excludes(three->get_option("--theta"));
  return [wearmap, commands]() {
    for (const auto& [sub, run] : commands)
      if (wearmap->got_subcommand(sub)) return run();
    return 2;
  };
}

}  // namespace wearscale::app
