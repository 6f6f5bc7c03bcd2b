// wearscale dem patch-test [CASE.toml] --material table-6.4|Si|SiO2 --lattice hcp|amorphous --d0 D
//                          [--nu NU] [--s S] [--no-strengths] [--set KEY=VALUE]... [--out DIR] [--json]
// wearscale dem junction   [CASE.toml] --material SiO2 --D 20e-9 --d0 6e-9 [--velocity V] [--pressure P]
//                          [--slide S] [--seed N] [--set KEY=VALUE]... [--out DIR] [--json]
// wearscale dem rough-shear [CASE.toml] --material SiO2 --d0 3e-9 [--length L] [--roughness SA_OVER_L]
//                          [--pressure P] [--velocity V] [--slide S] [--seed N] [--set KEY=VALUE]... [--out DIR] [--json]
// wearscale dem trapped-particles [CASE.toml] --material SiO2 --n 3 --D 18e-9 --d0 3e-9 [--length L]
//                          [--pressure P] [--velocity V] [--slide S] [--seed N] [--set KEY=VALUE]... [--out DIR] [--json]
// Every study also takes [--resume DIR].
// The coarse-grained DEM of thesis ch. 6-7: patch tests measuring E, ν, σ_m,N,
// σ_m,T beside their targets (§6.2), the sheared junction of §6.3, sheared
// rough surfaces (§7.2) and loose particles trapped between flat surfaces (§7.3).
// Each run checkpoints into its output folder (`checkpoint.h5`, policy from
// [run] checkpoint_interval / checkpoint_steps) and `--resume DIR` continues
// a killed or interrupted one.
#include <omp.h>

#include <algorithm>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/checkpoint.hpp"
#include "wearscale/core/config.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/output_lock.hpp"
#include "wearscale/core/output_set.hpp"
#include "wearscale/core/text_file.hpp"
#include "wearscale/coupling/plots.hpp"
#include "wearscale/dem/dem_study.hpp"

namespace wearscale::app {

namespace {

struct DemArgs {
  std::string case_file, out, resume;
  std::vector<std::pair<std::string, std::string>> flags;  // key, value
  std::vector<std::string> overrides;
  bool json = false;
  bool no_strengths = false;
};

// Adds `--name` writing the case key `key` (a.flags is reserved: slots stay put).
void flag(CLI::App* cmd, DemArgs& a, const std::string& name, const std::string& key, const std::string& help) {
  auto* slot = &a.flags.emplace_back(key, std::string());
  cmd->add_option(name, slot->second, fmt::format("{} ({})", help, key));
}

Config build_config(const DemArgs& a, const std::string& default_out, std::filesystem::path& out) {
  Config cfg = a.case_file.empty() ? Config::from_string("", "<command line>") : Config::load(a.case_file);
  for (const auto& [key, value] : a.flags)
    if (!value.empty()) cfg.override_value(fmt::format("{}={}", key, value));
  for (const auto& o : a.overrides) cfg.override_value(o);
  cfg.string_or("case.name", "dem");
  cfg.string_or("case.description", "");
  const std::string dir = cfg.string_or("output.dir", default_out);
  out = a.out.empty() ? std::filesystem::path(dir) : std::filesystem::path(a.out);
  return cfg;
}

// `written`: the files are this run's (else a completed run's, listed as they are).
int report(const DemArgs& a, const nlohmann::json& summary, bool written = true) {
  if (a.json) {
    std::cout << summary.dump(2) << '\n';
    return 0;
  }
  print_results(summary["results"]);
  for (const auto& f : summary["files"]) log::info("{} {}", written ? "wrote" : "kept", f.get<std::string>());
  return 0;
}

void common(CLI::App* cmd, DemArgs& a) {
  cmd->add_option("case", a.case_file, "Case file with a [dem] table (every flag is also a key there)");
  cmd->add_option("--set", a.overrides, "Override a case key: --set dem.patch_test.width=4 (repeatable)")
      ->expected(1)->take_all();
  cmd->add_option("--out", a.out, "Output folder");
  cmd->add_flag("--json", a.json, "Print one JSON object with the results and resolved parameters");
  cmd->add_option("--resume", a.resume,
                  "Continue the killed or interrupted run whose output folder is DIR from its checkpoint (same case "
                  "file, flags and --set options)")
      ->type_name("DIR");
}

// The command that continues an interrupted run: the case and every option as --set.
std::string resume_command(const DemArgs& a, const std::string& study, const std::filesystem::path& out) {
  std::string line = "wearscale dem " + study;
  if (!a.case_file.empty()) line += " " + a.case_file;
  for (const auto& [key, value] : a.flags)
    if (!value.empty()) line += fmt::format(" --set '{}={}'", key, value);
  for (const auto& o : a.overrides) line += fmt::format(" --set '{}'", o);
  // The threads too: a resumed run is bit for bit only on as many.
  return line + fmt::format(" -j {} --resume {}", std::max(1, omp_get_max_threads()), out.string());
}

using Study = nlohmann::json (*)(const Config&, const std::filesystem::path&, Checkpointer*);

// A measured E ≤ 0 or ν outside (−1, 0.5) is no elastic solid: the patch
// test failed to measure one (exit 1), whatever the sample did.
void require_elastic_bounds(const nlohmann::json& results) {
  const double e = results["young"]["value"].get<double>(), nu = results["poisson"]["value"].get<double>();
  if (!(e > 0.0) || !(nu > -1.0 && nu < 0.5))
    throw NumericalError("DEM patch test", 0, "elastic constants",
                         fmt::format("measured E = {:g}, ν = {:g}: not an elastic solid (allowed: E > 0, −1 < ν < 0.5); "
                                     "the sample did not respond elastically to the load (compare d0 with the printed "
                                     "d_min and the time step)",
                                     e, nu));
}

// One study, checkpointed into its output folder: fresh, or with --resume
// from the checkpoint there (or, if that run had completed, its summary).
// The junction and wear studies add the force-history plot.
int run_study(const DemArgs& a, const std::string& study, const std::string& default_out, const std::string& name,
              Study run, bool plot) {
  std::filesystem::path out;
  const Config cfg = build_config(a, default_out, out);
  const CheckpointPolicy policy = checkpoint_policy(cfg);
  const std::string fingerprint = case_fingerprint(cfg.to_json());
  if (!a.resume.empty()) out = resume_folder(a.resume, a.out);
  const OutputLock lock = OutputLock::folder(out, invocation());  // before its checkpoint is read
  Checkpointer checkpoints(out / "checkpoint.h5", fingerprint, policy);
  if (a.resume.empty()) require_fresh_start(checkpoints.file());
  if (!a.resume.empty()) {
    std::error_code ec;
    const auto done = out / (name + ".json");
    if (std::filesystem::exists(checkpoints.file(), ec)) {
      checkpoints.load();
    } else if (std::filesystem::exists(done, ec)) {
      nlohmann::json previous;
      try {
        previous = nlohmann::json::parse(read_text_file(done, "summary", std::uintmax_t{1} << 26));
      } catch (const nlohmann::json::exception& e) {
        throw InputError(fmt::format("{}: not a wearscale summary ({})", done.string(), e.what()));
      }
      const std::string was = previous.value("case_fingerprint", std::string());
      if (was != fingerprint) {
        const std::string diff = describe_case_difference(was, fingerprint);
        throw InputError(fmt::format("{}: this run completed with other parameters{}; resume with the case file and "
                                     "options it was run with, or write to another folder",
                                     done.string(), diff.empty() ? "" : " (" + diff + ")"));
      }
      if (const std::string broken = OutputSet::verify(out, previous); broken.empty()) {
        log::info("{}: already complete", out.string());
        return report(a, previous, false);
      } else {
        log::warn("{}: the outputs of the completed run are not intact ({}): the run starts again", out.string(),
                  broken);
      }
    } else {
      log::info("{}: no checkpoint yet: the run starts from the beginning", out.string());
    }
  }

  OutputSet outputs(out, name + ".json");  // published together, the summary last
  nlohmann::json summary;
  try {
    summary = run(cfg, out, &checkpoints);
  } catch (const Interrupted& e) {
    throw Interrupted(fmt::format("{}; continue with: {}", e.what(), resume_command(a, study, out)));
  }
  if (plot)
    if (auto png = coupling::plot_junction_force(out / (name + "_history.csv"), out / (name + "_force.png"),
                                                 summary["verdict"].get<std::string>()))
      summary["files"].push_back(png->string());
  require_finite_results(summary["results"], "DEM " + study);
  if (study == "patch-test") require_elastic_bounds(summary["results"]);
  summary["parameters"] = cfg.to_json();
  summary["case_fingerprint"] = fingerprint;
  summary["output_dir"] = out.string();
  outputs.commit(summary);
  if (checkpoints.saves() > 0)
    log::debug("{}: {} checkpoints written in {:.3f} s", out.string(), checkpoints.saves(), checkpoints.seconds_saving());
  checkpoints.discard();           // complete: nothing to resume
  remove_stale_partials(out);      // temporary files of a killed run this one did not continue
  return report(a, summary);
}

}  // namespace

Command add_dem(CLI::App& app) {
  auto* dem = app.add_subcommand("dem", "Coarse-grained cohesive DEM (thesis ch. 6-7): patch tests, sheared junctions, rough surfaces, trapped particles");
  dem->require_subcommand(1);

  auto* patch = dem->add_subcommand(
      "patch-test", "Measure E, ν (confined compression) and σ_m,N, σ_m,T (walls pulled, sheared) of a DEM sample (§6.2)");
  auto p = std::make_shared<DemArgs>();
  p->flags.reserve(16);
  common(patch, *p);
  flag(patch, *p, "--material", "dem.material", "table-6.4 (Table 6.4, unitless), Si, SiO2 or a [materials.define] name");
  flag(patch, *p, "--lattice", "dem.patch_test.lattice", "hcp or amorphous");
  flag(patch, *p, "--d0", "dem.patch_test.d0", "particle diameter (HCP) or mode of diameters, e.g. 90 or \"6 nm\"");
  flag(patch, *p, "--nu", "dem.poisson", "target Poisson's ratio, at most 0.25");
  flag(patch, *p, "--s", "dem.scaling_exponent", "size-scaling exponent s of (6.57)");
  flag(patch, *p, "--length", "dem.patch_test.length", "sample length L in d0");
  flag(patch, *p, "--seed", "dem.patch_test.seed", "seed of the amorphous sample");
  patch->add_flag("--no-strengths", p->no_strengths, "Only the elastic test (dem.patch_test.strengths = false)");

  auto* junction = dem->add_subcommand(
      "junction", "Shear a cylindrical junction between two surfaces (§6.3): plastic deformation or a rolling wear particle");
  auto j = std::make_shared<DemArgs>();
  j->flags.reserve(16);
  common(junction, *j);
  flag(junction, *j, "--material", "dem.material", "Si, SiO2 or a [materials.define] name");
  flag(junction, *j, "--D", "dem.junction.diameter", "junction diameter D, e.g. 20e-9 or \"20 nm\"");
  flag(junction, *j, "--d0", "dem.junction.d0", "mode of the particle diameters");
  flag(junction, *j, "--velocity", "dem.junction.velocity", "sliding velocity of the top wall");
  flag(junction, *j, "--pressure", "dem.junction.pressure", "normal pressure on the top wall");
  flag(junction, *j, "--slide", "dem.junction.sliding_distance", "sliding distance (default 1.5 D)");
  flag(junction, *j, "--seed", "dem.junction.seed", "seed of the amorphous sample");

  auto* rough = dem->add_subcommand(
      "rough-shear", "Shear two rough surfaces under a normal pressure (§7.2): worn particles, F_T history, Sa evolution");
  auto rs = std::make_shared<DemArgs>();
  rs->flags.reserve(16);
  common(rough, *rs);
  flag(rough, *rs, "--material", "dem.material", "Si, SiO2 or a [materials.define] name");
  flag(rough, *rs, "--d0", "dem.rough_shear.d0", "mode of the particle diameters");
  flag(rough, *rs, "--length", "dem.rough_shear.length", "cell length L (thesis: 25, 50, 100 d0)");
  flag(rough, *rs, "--roughness", "dem.rough_shear.roughness", "initial Sa / L (thesis: 0.01, 0.02, 0.04)");
  flag(rough, *rs, "--velocity", "dem.rough_shear.velocity", "sliding velocity of the top wall");
  flag(rough, *rs, "--pressure", "dem.rough_shear.pressure", "normal pressure on the top wall");
  flag(rough, *rs, "--slide", "dem.rough_shear.sliding_distance", "sliding distance (default L)");
  flag(rough, *rs, "--seed", "dem.rough_shear.seed", "seed of the amorphous sample and the profiles");

  auto* trapped = dem->add_subcommand(
      "trapped-particles",
      "Shear n loose particles trapped between flat surfaces (§7.3): rolling particles or a shear band");
  auto tp = std::make_shared<DemArgs>();
  tp->flags.reserve(16);
  common(trapped, *tp);
  flag(trapped, *tp, "--material", "dem.material", "Si, SiO2 or a [materials.define] name");
  flag(trapped, *tp, "--n", "dem.trapped_particles.count", "number of loose particles (thesis: 2 to 4)");
  flag(trapped, *tp, "--D", "dem.trapped_particles.diameter", "diameter of the loose particles (= the gap)");
  flag(trapped, *tp, "--d0", "dem.trapped_particles.d0", "mode of the particle diameters");
  flag(trapped, *tp, "--length", "dem.trapped_particles.length", "cell length L (default 3 n D)");
  flag(trapped, *tp, "--velocity", "dem.trapped_particles.velocity", "sliding velocity of the top wall");
  flag(trapped, *tp, "--pressure", "dem.trapped_particles.pressure", "normal pressure on the top wall");
  flag(trapped, *tp, "--slide", "dem.trapped_particles.sliding_distance", "sliding distance (default L)");
  flag(trapped, *tp, "--seed", "dem.trapped_particles.seed", "seed of the amorphous sample");

  return [dem, patch, p, junction, j, rough, rs, trapped, tp]() {
    if (dem->got_subcommand(rough))
      return run_study(*rs, "rough-shear", "out/dem-rough-shear", "rough_shear", dem::run_rough_shear_study, true);
    if (dem->got_subcommand(trapped))
      return run_study(*tp, "trapped-particles", "out/dem-trapped-particles", "trapped_particles",
                       dem::run_trapped_particles_study, true);
    if (dem->got_subcommand(patch)) {
      if (p->no_strengths) p->overrides.emplace_back("dem.patch_test.strengths=false");
      return run_study(*p, "patch-test", "out/dem-patch-test", "patch_test", dem::run_patch_test_study, false);
    }
    return run_study(*j, "junction", "out/dem-junction", "junction", dem::run_junction_study, true);
  };
}

}  // namespace wearscale::app
