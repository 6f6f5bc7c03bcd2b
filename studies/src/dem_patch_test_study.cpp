// The DEM patch test of §6.2 (`wearscale dem patch-test`, [dem.patch_test]):
// a sample between two walls in confined compression gives C11, C12 and so E
// and ν; the walls pulled apart and sheared give σ_m,N and σ_m,T, each beside
// its target.
#include <memory>
#include <span>
#include <string>
#include <vector>
#include <fmt/format.h>

#include "dem_case.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/progress.hpp"
#include "wearscale/dem/patch_test.hpp"
#include "wearscale/io/csv.hpp"

namespace wearscale::studies {

namespace {

using namespace dem;

nlohmann::json run_patch_test_study(const Config& root, RunContext& context) {
  const std::filesystem::path& out = context.output_dir();
  Checkpointer* checkpoints = &context.checkpoints();
  PatchTestSpec spec;
  spec.material = dem_material(root);
  require_cohesive_law(root, "patch test");
  spec.engine = read_engine(root);
  const Config c = root.section("dem.patch_test");
  const bool unitless = spec.material.name == "table-6.4";
  spec.amorphous = c.choice_or("lattice", "hcp", {"hcp", "amorphous"}) == "amorphous";
  const double d_c = critical_diameter(spec.material);  // d_c = 4γE/σ_m,N² (6.35)
  spec.d0 = c.has("d0") ? c.number("d0", Range::positive(), unitless ? units::dimensionless : units::length) : 0.6 * d_c;
  spec.load_along_c_axis = c.boolean_or("load_along_c_axis", false);
  spec.length = c.number_or("length", 25.0, Range::closed(PatchTestSpec::min_length, PatchTestSpec::max_length));
  // At least the largest particle (1.25 d0, amorphous); an HCP sample takes
  // whole cells of √(8/3) d0: 1.6 is one cell, the 2.4 nm depth of §7.1.1.
  spec.width = c.number_or("width", 3.0, Range::closed(PatchTestSpec::min_width, PatchTestSpec::max_width));
  spec.load = c.number_or("load", 0.01, Range::open(0.0, spec.material.tensile_strength / spec.material.young));
  spec.time_step = read_time_step(c);
  spec.strain_rate = c.number_or("strain_rate", 1e-5, Range::open(0.0, PatchTestSpec::max_strain_rate));
  spec.strengths = c.boolean_or("strengths", true);
  spec.max_elastic_steps = c.integer_or("max_elastic_steps", 40000,
                                        Range::at_least(static_cast<double>(PatchTestSpec::min_elastic_steps)));
  spec.seed = static_cast<unsigned>(read_seed(c));
  root.reject_unknown_keys();

  log::info("DEM patch test: {} {}, d0 = {:g} (d_min = {:g}, d_c = {:g}), ν target {:g}", spec.amorphous ? "amorphous" : "HCP",
            spec.material.name, spec.d0, minimum_diameter(spec.material), d_c, spec.material.poisson);
  std::unique_ptr<Progress> bar;
  std::string phase;
  const auto hooks = study_checkpoints(checkpoints, "dem/patch_test", nullptr);
  const auto result = run_patch_test(
      spec,
      [&](const std::string& name, long done, long planned) {
        if (name != phase) {
          bar = std::make_unique<Progress>("patch test: " + name, static_cast<double>(planned));
          phase = name;
        }
        bar->update(static_cast<double>(done));
      },
      hooks);
  bar.reset();

  const std::string stress_unit = unitless ? "1" : "Pa";
  context.report("young", result.young, stress_unit, fmt::format("measured E (target {:g})", spec.material.young));
  context.report("poisson", result.poisson, "1", fmt::format("measured ν (target {:g})", spec.material.poisson));
  context.report("d_min", result.d_min, unitless ? "1" : "m", "minimum particle size 4γ/σ_m,N (6.62)");
  context.report("d_c", result.d_c, unitless ? "1" : "m", "critical particle size 4γE/σ_m,N² (6.35)");
  context.report("particles", static_cast<double>(result.particles), "1", "particles in the sample");
  context.report("elastic_steps", static_cast<double>(result.elastic_steps), "1",
         result.elastic_converged ? "steps to rest under the load" : "steps run (the wall had not stopped)");
  std::vector<std::string> names{"E", "nu"};
  std::vector<double> measured{result.young, result.poisson}, target{spec.material.young, spec.material.poisson};
  if (result.tensile_strength) {
    context.report("tensile_strength", *result.tensile_strength, stress_unit,
           fmt::format("peak σ_yy in tension (target {:g}, (6.63))", result.target_tensile));
    context.report("shear_strength", *result.shear_strength, stress_unit,
           fmt::format("peak σ_xy in shear (target {:g})", result.target_shear));
    names.insert(names.end(), {"sigma_mN", "sigma_mT"});
    measured.insert(measured.end(), {*result.tensile_strength, *result.shear_strength});
    target.insert(target.end(), {result.target_tensile, result.target_shear});
  }
  // One row: each quantity measured and its target, in its own unit.
  std::vector<std::string> columns, units;
  std::vector<std::vector<double>> values;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string unit = names[k] == "nu" ? "1" : stress_unit;
    columns.insert(columns.end(), {names[k], names[k] + "_target"});
    units.insert(units.end(), {unit, unit});
    values.push_back({measured[k]});
    values.push_back({target[k]});
  }
  const std::vector<std::span<const double>> spans(values.begin(), values.end());
  const auto csv = out / "patch_test.csv";
  write_csv(csv, columns, spans, units,
            {fmt::format("DEM patch test (§6.2), {} {}, d0 = {:g}", spec.amorphous ? "amorphous" : "HCP", spec.material.name, spec.d0),
             "each quantity measured and its target (<name>_target)"});
  return {{"files", {csv.string()}}};
}

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

class PatchTestStudy final : public DemStudy {
 public:
  std::string name() const override { return "dem/patch_test"; }
  std::string summary() const override {
    return "E, ν (confined compression) and σ_m,N, σ_m,T (walls pulled, sheared) of a DEM sample (§6.2)";
  }
  Schema schema() const override {
    const std::string t = "dem.patch_test";
    Schema s = material_keys({.materials = "table-6.4 (Table 6.4, unitless), Si, SiO2 or a [materials.define] name",
                              .poisson_flag = "--nu",
                              .scaling_exponent_flag = "--s"});
    s.insert(s.end(),
             {{t + ".lattice", "choice", "hcp | amorphous", "", "hcp", "sample lattice", "--lattice"},
              {t + ".d0", "number", "> 0", "m", "0.6 d_c",
               "particle diameter (HCP) or mode of diameters, e.g. 90 or \"6 nm\"", "--d0"},
              {t + ".length", "number", "[6, 400]", "1", "25", "sample length L in d0", "--length"},
              {t + ".width", "number", "[1.25, 100]", "1", "3", "sample width in d0", ""},
              seed_key(t),
              {t + ".strengths", "boolean", "", "", "true", "also pull and shear the walls", "--no-strengths",
               "false"},
              {t + ".load_along_c_axis", "boolean", "", "", "false",
               "HCP: the c axis (stacking direction) along the load", ""},
              {t + ".load", "number", "(0, σ_m,N/E)", "1", "0.01", "compressive stress of the elastic test, in E", ""},
              time_step_key(t),
              {t + ".strain_rate", "number", "(0, 0.01)", "1", "1e-5", "strength tests: ε̇ Δt", ""},
              {t + ".max_elastic_steps", "integer", "≥ 1000", "1", "40000",
               "step limit of the elastic compression", ""}});
    return s;
  }
  void run(const Config& inputs, RunContext& context) override {
    const EngineRanks ranks(engine_);
    const auto outputs = run_patch_test_study(inputs, context);
    require_elastic_bounds(context.results());
    finish(outputs, context, "");
  }
};

}  // namespace
}  // namespace wearscale::studies

WEARSCALE_STUDY(PatchTestStudy)
