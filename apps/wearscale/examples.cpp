#include "examples.hpp"

#include <map>
#include <string>
#include <vector>

namespace wearscale::app {

namespace {

const std::string pod = "wearscale run cases/pin_on_disc_si_oxide.toml --set scale.macro.grid=32 "
                        "--set scale.macro.distance=0.001 --out pod";
const std::string generate = "wearscale surface generate --n 128 --size \"100 um\" --hurst 0.8 --kl 2 --kr 4 --ks 32 "
                             "--hprime-rms 0.5 --seed 1 --out rough    # rough/surface.h5 (+ .xdmf)";
const std::string patch_test = "wearscale dem patch-test --lattice hcp --nu 0.1 --length 12 --no-strengths --out patch";
const std::string analytic2d = "wearscale wearmap analytic2d --n 40 --out map2d";

// Command path (the words after the program) → its examples, each "command  # what it shows".
const std::map<std::string, std::vector<std::string>>& table() {
  static const std::map<std::string, std::vector<std::string>> examples = {
      {"",
       {"wearscale run cases/hertz_pin.toml --out hertz    # closed-form Hertz contact of the unworn pin",
        pod + "    # a short pin-on-disc on a coarse grid", "wearscale --help-all    # every command's help"}},
      {"run",
       {"wearscale run cases/hertz_pin.toml --out hertz", pod + "    # 1 mm of sliding on a 32² grid",
        "wearscale run cases/oxide_thickness_sweep.toml --set scale.macro.grid=32 --set scale.macro.distance=0.001 "
        "--out sweep    # the oxide-thickness sweep, coarse"}},
      {"check",
       {"wearscale check cases/pin_on_disc_si_oxide.toml    # the resolved case, every default, the memory; nothing "
        "written",
        "wearscale check cases/oxide_thickness_sweep.toml --set scale.macro.grid=32 --json"}},
      {"backends", {"wearscale backends", "wearscale backends --json"}},
      {"studies", {"wearscale studies", "wearscale studies dem/patch_test    # its case keys", "wearscale studies contact --json"}},
      {"version", {"wearscale version", "wearscale version --json"}},
      {"surface", {generate, "wearscale surface analyze rough/surface.h5 --no-window    # periodic: no window"}},
      {"surface generate", {generate}},
      {"surface analyze", {generate, "wearscale surface analyze rough/surface.h5 --no-window --psd-out psd.csv --out psd --json"}},
      {"contact",
       {"wearscale contact cases/rough_contact.toml --set contact.grid=128 --out rough-contact",
        "wearscale contact --set contact.grid=64 --set contact.size=1 --set contact.sphere.radius=10 "
        "--set contact.young=1 --poisson 0.5 --pressure 1.5e-4 --friction coulomb --mu 0.5 "
        "--tangential-pressure 4e-5 --tensile-strength 1e-3 --out mindlin    # Mindlin partial slip (Fig. A.4a)"}},
      {"strength-table",
       {"wearscale strength-table --backend lammps --material Si --pressures 0,5 --set md.sample_steps=200 "
        "--out si    # two pressures with LAMMPS's smoke preset: si/lammps_smoke_Si.csv (tens of seconds; cached afterwards)"}},
      {"dem", {patch_test}},
      {"dem patch-test", {patch_test, "wearscale dem patch-test cases/dem_patch_test.toml --set dem.patch_test.length=12 "
                                      "--no-strengths --out patch-case"}},
      {"dem junction",
       {"wearscale dem junction --material SiO2 --D 20e-9 --d0 \"6 nm\" --slide \"3 nm\" --out junction"}},
      {"dem rough-shear",
       {"wearscale dem rough-shear --material SiO2 --d0 \"6 nm\" --length \"60 nm\" --velocity 50 --slide \"12 nm\" "
        "--roughness 0.04 --set dem.rough_shear.height='\"60 nm\"' --out rough-shear"}},
      {"dem trapped-particles",
       {"wearscale dem trapped-particles --material SiO2 --n 2 --D 20e-9 --d0 \"6 nm\" --velocity 100 "
        "--slide \"12 nm\" --out trapped"}},
      {"dem oxide-asperity",
       {"wearscale dem oxide-asperity --d0 \"6 nm\" --D 20e-9 --velocity 100 --slide \"12 nm\" "
        "--set dem.oxide_asperity.box='[\"60 nm\", \"30 nm\", \"65 nm\"]' --out oxide-asperity    # a small cell"}},
      {"wearmap", {analytic2d}},
      {"wearmap analytic2d", {analytic2d + "    # Fig. 3.7 on a 40² grid"}},
      {"wearmap analytic3d", {"wearscale wearmap analytic3d --interaction max --n 41 --out map3d    # Fig. 4.6"}},
      {"wearmap rough",
       {"wearscale wearmap rough --n 32 --ql 2 --seeds 1 --n-loads 2 --n-dstar 2 --out map-rough    # tiny surfaces"}},
      {"merge",
       {"wearscale run cases/oxide_thickness_sweep.toml --set scale.macro.grid=32 --set scale.macro.distance=0.001 "
        "--task 1/2 --out shards    # shard 1 of 2 (a job array's task; runs 1, 3, 5)",
        "wearscale run cases/oxide_thickness_sweep.toml --set scale.macro.grid=32 --set scale.macro.distance=0.001 "
        "--task 2/2 --out shards    # shard 2 of 2, into the same folder",
        "wearscale merge shards    # the sweep's table, plots and summary.json, once both are done",
        "wearscale wearmap rough --n 32 --ql 2 --seeds 2 --n-loads 2 --n-dstar 2 --task 1/2 --out map-shards    # "
        "surface 1 of a map",
        "wearscale wearmap rough --n 32 --ql 2 --seeds 2 --n-loads 2 --n-dstar 2 --task 2/2 --out map-shards    # "
        "surface 2",
        "wearscale merge map-shards    # the map from the surfaces the shards kept in map-shards/tasks"}},
      {"completion",
       {"source <(wearscale completion bash)", "wearscale completion zsh > _wearscale    # into a folder of $fpath"}},
  };
  return examples;
}

void set(CLI::App& app, const std::string& path) {
  if (const auto it = table().find(path); it != table().end()) {
    std::string footer = "\nExamples:\n";
    for (const auto& line : it->second) footer += "  " + line + "\n";
    app.footer(footer);
  } else {
    app.footer("");  // not the parent's (CLI11 copies it into a new subcommand)
  }
  for (auto* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    set(*sub, path.empty() ? sub->get_name() : path + " " + sub->get_name());
}

}  // namespace

void add_examples(CLI::App& app) { set(app, ""); }

}  // namespace wearscale::app
