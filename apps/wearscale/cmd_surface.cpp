// wearscale surface generate [CASE.toml] --n N --size L --hurst H --kl K --ks K (--hprime-rms X | --h-rms X | --sa X)
//                            [--set KEY=VALUE]... [--out DIR] [--json]
// wearscale surface analyze FILE [--dataset D] [--size L] [--qmin Q --qmax Q] [--no-window] [--psd-out NAME.csv]
//                            [--set KEY=VALUE]... [--out DIR] [--json]
// Rough surfaces of thesis §1.1.2 (Fig. 1.3) and the topography analysis of
// §8.1.1: the studies of studies/src/surface_*_study.cpp, each subcommand's
// flags the aliases its schema declares.
#include <vector>

#include "study_command.hpp"

namespace wearscale::app {

Command add_surface(CLI::App& app) {
  auto* surface = app.add_subcommand("surface", "Rough surfaces: generate one from a PSD, analyze a topography "
                                                "(Sa, h_RMS, h'_RMS, radial PSD, Hurst exponent)");
  surface->require_subcommand(1);
  struct Entry {
    const char *command, *study, *set_example;  // a key of the study's own for --set's help
  };
  const Entry studies[] = {{"generate", "surface/generate", "surface.generate.seed=2"},
                           {"analyze", "surface/analyze", "surface.analyze.q_min=1e5"}};
  std::vector<std::pair<CLI::App*, Command>> commands;
  for (const auto& [command, study, set_example] : studies) {
    auto run = add_study_command(*surface, command, study, studies::study_registry().create(study)->summary(),
                                 set_example);
    commands.emplace_back(surface->get_subcommands({}).back(), std::move(run));
  }
  // One roughness target.
  auto* generate = surface->get_subcommand("generate");
  generate->get_option("--hprime-rms")->excludes(generate->get_option("--h-rms"))->excludes(generate->get_option("--sa"));
  generate->get_option("--h-rms")->excludes(generate->get_option("--sa"));
  return [surface, commands]() {
    for (const auto& [sub, run] : commands)
      if (surface->got_subcommand(sub)) return run();
    return 2;
  };
}

}  // namespace wearscale::app
