// wearscale contact [CASE.toml] [--surface F] [--pressure P | --load F | --interference D]
//                   [--e-star E] [--set KEY=VALUE]... [--out DIR] [--json]
// Frictionless normal contact of a rigid surface on an elastic flat (BEM).
#include <iostream>

#include <fmt/format.h>

#include "commands.hpp"
#include "wearscale/bem/contact_study.hpp"
#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/config.hpp"
#include "wearscale/core/log.hpp"

namespace wearscale::app {

namespace {
struct ContactArgs {
  std::string case_file, surface, pressure, load, interference, e_star, out;
  std::vector<std::string> overrides;
  bool json = false;
};
}  // namespace

Command add_contact(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "contact", "Normal contact of a rigid surface (file, generated rough surface, sphere) on an elastic flat");
  auto a = std::make_shared<ContactArgs>();
  cmd->add_option("case", a->case_file, "Case file with a [contact] table (e.g. cases/rough_contact.toml)");
  cmd->add_option("--surface", a->surface, "Height file (HDF5 /surface/height, or CSV/text grid): contact.surface");
  cmd->add_option("--pressure", a->pressure, "Imposed mean pressure, e.g. 1e6 or \"1 MPa\": contact.mean_pressure");
  cmd->add_option("--load", a->load, "Imposed normal force on the cell: contact.normal_load");
  cmd->add_option("--interference", a->interference, "Imposed interference: contact.interference");
  cmd->add_option("--e-star", a->e_star, "Contact modulus E* (1.12): contact.e_star");
  cmd->add_option("--set", a->overrides, "Override a case key: --set contact.rough.seed=3 (repeatable)")
      ->expected(1)->take_all();
  cmd->add_option("--out", a->out, "Output folder (default: [output].dir, else out/contact)");
  cmd->add_flag("--json", a->json, "Print one JSON object with the headline results and resolved parameters");
  return [a]() {
    Config cfg = a->case_file.empty() ? Config::from_string("", "<command line>") : Config::load(a->case_file);
    const std::pair<const std::string*, const char*> flags[] = {{&a->surface, "contact.surface"},
                                                                {&a->pressure, "contact.mean_pressure"},
                                                                {&a->load, "contact.normal_load"},
                                                                {&a->interference, "contact.interference"},
                                                                {&a->e_star, "contact.e_star"}};
    for (const auto& [value, key] : flags)
      if (!value->empty()) cfg.override_value(fmt::format("{}={}", key, *value));
    for (const auto& o : a->overrides) cfg.override_value(o);
    cfg.string_or("case.name", "contact");
    cfg.string_or("case.description", "");
    const std::string dir = cfg.string_or("output.dir", "out/contact");
    const std::filesystem::path out = a->out.empty() ? std::filesystem::path(dir) : std::filesystem::path(a->out);
    auto summary = bem::run_contact_study(cfg, out);
    summary["parameters"] = cfg.to_json();
    summary["output_dir"] = out.string();
    write_file_atomically(out / "summary.json", summary.dump(2) + "\n");
    if (a->json) {
      std::cout << summary.dump(2) << '\n';
      return 0;
    }
    print_results(summary["results"]);
    for (const auto& f : summary["files"]) log::info("wrote {}", f.get<std::string>());
    return 0;
  };
}

}  // namespace wearscale::app
