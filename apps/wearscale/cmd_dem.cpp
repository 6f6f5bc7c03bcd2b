// wearscale dem patch-test [CASE.toml] --material table-6.4|Si|SiO2 --lattice hcp|amorphous --d0 D
//                          [--nu NU] [--s S] [--no-strengths] [--set KEY=VALUE]... [--out DIR] [--json]
// wearscale dem junction   [CASE.toml] --material SiO2 --D 20e-9 --d0 6e-9 [--velocity V] [--pressure P]
//                          [--slide S] [--seed N] [--set KEY=VALUE]... [--out DIR] [--json]
// wearscale dem rough-shear [CASE.toml] --material SiO2 --d0 3e-9 [--length L] [--roughness SA_OVER_L]
//                          [--pressure P] [--velocity V] [--slide S] [--seed N] [--set KEY=VALUE]... [--out DIR] [--json]
// wearscale dem trapped-particles [CASE.toml] --material SiO2 --n 3 --D 18e-9 --d0 3e-9 [--length L]
//                          [--pressure P] [--velocity V] [--slide S] [--seed N] [--set KEY=VALUE]... [--out DIR] [--json]
// wearscale dem oxide-asperity [CASE.toml] [--d0 D0] [--D D] [--pressure P] [--velocity V] [--slide S]
//                          [--seed N] [--set KEY=VALUE]... [--out DIR] [--json]
// Every study also takes [--resume DIR].
// The DEM studies of studies/src/dem_*_study.cpp; each subcommand's flags are
// the aliases its schema declares.
#include <vector>

#include "study_command.hpp"

namespace wearscale::app {

Command add_dem(CLI::App& app) {
  auto* dem = app.add_subcommand(
      "dem", "Coarse-grained cohesive DEM (thesis ch. 6-7): patch tests, sheared junctions, rough surfaces, trapped particles, "
      "an oxidized asperity");
  dem->require_subcommand(1);
  struct Entry {
    const char *command, *study, *set_example;  // a key of the study's own for --set's help
  };
  const Entry studies[] = {{"patch-test", "dem/patch_test", "dem.patch_test.width=4"},
                           {"junction", "dem/junction", "dem.junction.seed=2"},
                           {"rough-shear", "dem/rough_shear", "dem.rough_shear.seed=2"},
                           {"trapped-particles", "dem/trapped_particles", "dem.trapped_particles.seed=2"},
                           {"oxide-asperity", "dem/oxide_asperity", "dem.oxide_asperity.seed=2"}};
  std::vector<std::pair<CLI::App*, Command>> commands;
  for (const auto& [command, study, set_example] : studies) {
    auto run = add_study_command(*dem, command, study, studies::study_registry().create(study)->summary(),
                                 set_example);
    commands.emplace_back(dem->get_subcommands({}).back(), std::move(run));
  }
  return [dem, commands]() {
    for (const auto& [sub, run] : commands)
      if (dem->got_subcommand(sub)) return run();
    return 2;
  };
}

}  // namespace wearscale::app
