// wearscale strength-table [CASE.toml] --backend lammps --material Si|SiO2 --pressures 0,10,25
//                          [--preset smoke|thesis] [--lmp PATH] [--ranks N] [--set KEY=VALUE]...
//                          [--out FILE.csv] [--json]
// Molecular shear strengths σ_max(p), σ_dyn(p) from the MD shear test of
// §9.3.1 run with LAMMPS, written as a strength table (materials/ format).
// --pressures takes plain numbers in GPa; case keys (md.pressures, --set)
// take SI numbers or unit strings ("10 GPa").
#include <iostream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "wearscale/core/config.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/materials/strength_table.hpp"
#include "wearscale/md/shear_study.hpp"
#include "wearscale/coupling/shear_test_keys.hpp"

namespace wearscale::app {

namespace {

struct StrengthTableArgs {
  std::string case_file, backend, material, pressures, preset, lmp, ranks, out;
  std::vector<std::string> overrides;
  bool json = false;
};

std::string toml_string(const std::string& s) {
  std::string q = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') q += '\\';
    q += c;
  }
  return q + "\"";
}

// "0,10,25" (GPa) → ["0 GPa", "10 GPa", "25 GPa"] as a TOML array.
std::string pressures_to_toml(const std::string& list) {
  std::stringstream ss(list);
  std::string item, out;
  while (std::getline(ss, item, ',')) {
    const auto b = item.find_first_not_of(" \t"), e = item.find_last_not_of(" \t");
    item = b == std::string::npos ? std::string() : item.substr(b, e - b + 1);
    char* end = nullptr;
    std::strtod(item.c_str(), &end);
    if (item.empty() || end == item.c_str() || *end != '\0')
      throw InputError(fmt::format("--pressures '{}': '{}' is not a number; --pressures takes plain numbers in GPa "
                                   "separated by commas, e.g. --pressures 0,10,25 (unit strings go in a case key: "
                                   "--set 'md.pressures=[\"0 GPa\", \"10 GPa\"]')",
                                   list, item));
    out += fmt::format("{}\"{} GPa\"", out.empty() ? "" : ", ", item);
  }
  return "[" + out + "]";
}

}  // namespace

Command add_strength_table(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "strength-table",
      "Shear strengths sigma_max(p), sigma_dyn(p) of Si or SiO2 from the MD shear test of §9.3.1 (LAMMPS), written "
      "as a strength table. Identical inputs are read from the cache ($WEARSCALE_CACHE, else "
      "~/.cache/wearscale/lammps) instead of running lmp again.");
  auto a = std::make_shared<StrengthTableArgs>();
  cmd->add_option("case", a->case_file, "Case file with an [md] table (every flag below is also a key there)");
  cmd->add_option("--backend", a->backend, "Molecular backend: lammps (md.backend)")->check(CLI::IsMember({"lammps"}));
  cmd->add_option("--material", a->material, "Si or SiO2 (md.material)")->check(CLI::IsMember({"Si", "SiO2"}));
  cmd->add_option("--pressures", a->pressures,
                  "Normal pressures, plain numbers in GPa separated by commas, e.g. 0,10,25 (md.pressures, which "
                  "takes Pa or unit strings)");
  cmd->add_option("--preset", a->preset,
                  "smoke (small boxes, 100 m/s: seconds to a minute per pressure) or thesis (10 nm boxes, 10 m/s: "
                  "hours per pressure) (md.preset, default smoke)")
      ->check(CLI::IsMember({"smoke", "thesis"}));
  cmd->add_option("--lmp", a->lmp, "LAMMPS executable (md.lmp; default: lmp on PATH)");
  cmd->add_option("--ranks", a->ranks, "MPI ranks, through mpirun when > 1 (md.ranks)");
  cmd->add_option("--set", a->overrides,
                  "Override a case key, e.g. --set md.shear_velocity=\"10 m/s\" --set md.window=[0.35,0.5] "
                  "(repeatable; keys: material preset pressures lateral_size height lattice_constant wall_thickness "
                  "thermostat_thickness shear_velocity temperature langevin_damp timestep compression_time "
                  "strain_end window sample_steps seed potential cutoff lmp ranks cache cache_dir quench.*)")
      ->expected(1)
      ->take_all();
  cmd->add_option("--out", a->out, "Table file, .csv or .h5 (output.file; default out/strength-table/lammps_<preset>_<material>.csv)");
  cmd->add_flag("--json", a->json, "Print one JSON object with the table, its provenance and the resolved parameters");
  return [a]() {
    Config cfg = a->case_file.empty() ? Config::from_string("", "<command line>") : Config::load(a->case_file);
    if (!a->backend.empty()) cfg.override_value("md.backend=" + toml_string(a->backend));
    if (!a->material.empty()) cfg.override_value("md.material=" + toml_string(a->material));
    if (!a->pressures.empty()) cfg.override_value("md.pressures=" + pressures_to_toml(a->pressures));
    if (!a->preset.empty()) cfg.override_value("md.preset=" + toml_string(a->preset));
    if (!a->lmp.empty()) cfg.override_value("md.lmp=" + toml_string(a->lmp));
    if (!a->ranks.empty()) cfg.override_value("md.ranks=" + a->ranks);
    if (!a->out.empty()) cfg.override_value("output.file=" + toml_string(a->out));
    for (const auto& o : a->overrides) cfg.override_value(o);

    cfg.string_or("case.name", "strength-table");
    cfg.string_or("case.description", "");
    cfg.choice_or("md.backend", "lammps", {"lammps"});
    const md::ShearTestSpec spec = coupling::read_shear_test_spec(cfg);
    if (spec.pressures.size() < 2)
      throw cfg.error("md.pressures", "a strength table needs at least two pressures", "two or more pressures");
    const std::string out = cfg.string_or(
        "output.file", fmt::format("out/strength-table/lammps_{}_{}.csv", spec.preset, md::to_string(spec.material)));
    cfg.reject_unknown_keys();

    const md::ShearStudy study = md::run_shear_study(spec);
    const materials::StrengthTable table = md::strength_table(study);
    const std::filesystem::path file(out);
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
    materials::write_strength_table(file, table);

    if (a->json) {
      nlohmann::json j;
      j["material"] = table.material;
      j["backend"] = "lammps";
      j["preset"] = spec.preset;
      j["file"] = file.string();
      j["lammps_version"] = study.lammps_version;
      for (const auto& p : study.points)
        j["rows"].push_back({{"pressure_GPa", p.pressure / 1e9},
                             {"sigma_max_GPa", p.strength.sigma_max / 1e9},
                             {"sigma_dyn_GPa", p.strength.sigma_dyn / 1e9},
                             {"strain_at_max", p.strength.strain_at_max},
                             {"sigma_dyn_std_GPa", p.strength.sigma_dyn_std / 1e9},
                             {"temperature_window_K", p.strength.temperature_window},
                             {"cached", p.run.cached},
                             {"wall_seconds", p.run.wall_seconds}});
      for (const auto& [k, v] : table.provenance) j["provenance"][k] = v;
      j["parameters"] = cfg.to_json();
      std::cout << j.dump(2) << '\n';
      return 0;
    }
    std::cout << fmt::format("# {} shear strengths (MD shear test §9.3.1, LAMMPS {}, preset {})\n", table.material,
                             study.lammps_version, spec.preset);
    std::cout << fmt::format("{:>12} {:>14} {:>14}\n", "pressure_GPa", "sigma_max_GPa", "sigma_dyn_GPa");
    for (std::size_t i = 0; i < table.pressure.size(); ++i)
      std::cout << fmt::format("{:>12.6g} {:>14.4f} {:>14.4f}\n", table.pressure[i] / 1e9, table.sigma_max[i] / 1e9,
                               table.sigma_dyn[i] / 1e9);
    log::info("wrote {}", file.string());
    return 0;
  };
}

}  // namespace wearscale::app
