// wearscale contact [CASE.toml] [--surface F] [--pressure P | --load F | --interference D]
//                   [--e-star E] [--poisson NU] [--friction coulomb|tresca [--mu M | --shear-strength S]
//                   [--tangential-pressure Q] [--tensile-strength SM]] [--set KEY=VALUE]... [--out DIR] [--json]
// Normal (frictionless) or frictional contact of a rigid surface on an elastic flat (BEM).
#include <iostream>

#include <fmt/format.h>

#include "commands.hpp"
#include "wearscale/bem/contact_study.hpp"
#include "wearscale/bem/slab_contact_study.hpp"
#include "wearscale/bem/topography_io.hpp"
#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/config.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/core/output_lock.hpp"
#include "wearscale/core/output_set.hpp"

namespace wearscale::app {

namespace {
struct ContactArgs {
  std::string case_file, surface, missing, pressure, load, interference, e_star, out;
  std::string poisson, friction, mu, shear_strength, tangential, tensile_strength;
  std::vector<std::string> overrides;
  bool json = false;
};
}  // namespace

Command add_contact(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "contact",
      "Normal or frictional contact of a rigid surface (file, generated rough surface, sphere) on an elastic flat");
  auto a = std::make_shared<ContactArgs>();
  cmd->add_option("case", a->case_file, "Case file with a [contact] table (e.g. cases/rough_contact.toml)");
  cmd->add_option("--surface", a->surface, "Height file: " + bem::supported_topography_formats() + ": contact.surface");
  cmd->add_option("--missing", a->missing,
                  std::string(bem::MissingPointsChoice::doc) + ": contact." + bem::MissingPointsChoice::key);
  cmd->add_option("--pressure", a->pressure, "Imposed mean pressure, e.g. 1e6 or \"1 MPa\": contact.mean_pressure");
  cmd->add_option("--load", a->load, "Imposed normal force on the cell: contact.normal_load");
  cmd->add_option("--interference", a->interference, "Imposed interference: contact.interference");
  cmd->add_option("--e-star", a->e_star, "Contact modulus E* (1.12): contact.e_star");
  cmd->add_option("--poisson", a->poisson, "Poisson's ratio ν of the elastic flat: contact.poisson");
  cmd->add_option("--friction", a->friction, "Friction law (Appendix A): coulomb | tresca | none: contact.friction");
  cmd->add_option("--mu", a->mu, "Coulomb friction coefficient μ (A.2): contact.friction_coefficient");
  cmd->add_option("--shear-strength", a->shear_strength,
                  "Tresca shear strength σ_m,T (A.3), e.g. \"250 MPa\": contact.shear_strength");
  cmd->add_option("--tangential-pressure", a->tangential, "Imposed mean tangential traction along x: "
                  "contact.tangential_pressure");
  cmd->add_option("--tensile-strength", a->tensile_strength,
                  "Tensile strength σ_m: crack initiation (4.25) per micro-contact: contact.tensile_strength");
  cmd->add_option("--set", a->overrides, "Override a case key: --set contact.rough.seed=3 (repeatable)")
      ->expected(1)->take_all();
  cmd->add_option("--out", a->out, "Output folder (default: [output].dir, else out/contact)");
  cmd->add_flag("--json", a->json, "Print one JSON object with the headline results and resolved parameters");
  return [a]() {
    Config cfg = a->case_file.empty() ? Config::from_string("", "<command line>") : Config::load(a->case_file);
    const std::pair<const std::string*, const char*> flags[] = {{&a->surface, "contact.surface"},
                                                                {&a->missing, "contact.missing"},
                                                                {&a->pressure, "contact.mean_pressure"},
                                                                {&a->load, "contact.normal_load"},
                                                                {&a->interference, "contact.interference"},
                                                                {&a->e_star, "contact.e_star"},
                                                                {&a->poisson, "contact.poisson"},
                                                                {&a->friction, "contact.friction"},
                                                                {&a->mu, "contact.friction_coefficient"},
                                                                {&a->shear_strength, "contact.shear_strength"},
                                                                {&a->tangential, "contact.tangential_pressure"},
                                                                {&a->tensile_strength, "contact.tensile_strength"}};
    for (const auto& [value, key] : flags)
      if (!value->empty()) cfg.override_value(fmt::format("{}={}", key, *value));
    for (const auto& o : a->overrides) cfg.override_value(o);
    cfg.string_or("case.name", "contact");
    cfg.string_or("case.description", "");
    const std::string dir = cfg.string_or("output.dir", "out/contact");
    const std::filesystem::path out = a->out.empty() ? std::filesystem::path(dir) : std::filesystem::path(a->out);
    if (mpi::size() > 1 && !mpi::is_root()) {  // mpirun -np P: this rank's slab; rank 0 locks and writes
      log::set_level(log::Level::Quiet);
      (void)bem::run_slab_contact_study(cfg, out);
      return 0;
    }
    const OutputLock lock = OutputLock::folder(out, invocation());
    OutputSet outputs(out, "summary.json");  // published together, summary.json last
    auto summary = mpi::size() > 1 ? bem::run_slab_contact_study(cfg, out) : bem::run_contact_study(cfg, out);
    require_finite_results(summary["results"], "contact study");
    summary["parameters"] = cfg.to_json();
    summary["output_dir"] = out.string();
    outputs.commit(summary);
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
