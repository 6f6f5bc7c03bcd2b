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

// The unitless material of Table 6.4: its lengths (d0) carry no unit.
bool is_unitless(const CohesiveMaterial& m) { return m.name == "table-6.4"; }

const KeyTable<PatchTestSpec>& patch_test_keys() {
  using S = PatchTestSpec;
  static const auto table = [] {
    KeyTable<S> t;
    t.choice("lattice", &S::amorphous, std::vector<std::pair<std::string, bool>>{{"hcp", false}, {"amorphous", true}},
             "sample lattice")
        .flag("--lattice")
        .custom("d0", "number", "> 0", "m", "particle diameter (HCP) or mode of diameters, e.g. 90 or \"6 nm\"",
                [](const Config& c, const std::string& key, S& s) {
                  s.d0 = c.has(key) ? c.number(key, Range::positive(),
                                               is_unitless(s.material) ? units::dimensionless : units::length)
                                    : patch_test_d0(s.material);
                })
        .fallback("0.6 d_c")
        .flag("--d0")
        .boolean("load_along_c_axis", &S::load_along_c_axis, "HCP: the c axis (stacking direction) along the load")
        .number("length", &S::length, Range::closed(S::min_length, S::max_length), "sample length L in d0")
        .flag("--length")
        // At least the largest particle (1.25 d0, amorphous); an HCP sample takes
        // whole cells of √(8/3) d0: 1.6 is one cell, the 2.4 nm depth of §7.1.1.
        .number("width", &S::width, Range::closed(S::min_width, S::max_width), "sample width in d0")
        .number("load", &S::load, Range::positive(), "compressive stress of the elastic test, in E")
        .range_from([](const S& s) { return Range::open(0.0, s.material.tensile_strength / s.material.young); },
                    "(0, σ_m,N/E)");
    add_time_step(t, &S::time_step);
    t.number("strain_rate", &S::strain_rate, Range::open(0.0, S::max_strain_rate), "strength tests: ε̇ Δt")
        .boolean("strengths", &S::strengths, "also pull and shear the walls")
        .flag("--no-strengths", "false")
        .integer("max_elastic_steps", &S::max_elastic_steps, Range::at_least(static_cast<double>(S::min_elastic_steps)),
                 "step limit of the elastic compression");
    add_seed(t, &S::seed);
    return t;
  }();
  return table;
}

nlohmann::json run_patch_test_study(const Config& root, const DemInputs& dem, RunContext& context) {
  const std::filesystem::path& out = context.output_dir();
  Checkpointer* checkpoints = &context.checkpoints();
  PatchTestSpec spec;
  spec.material = dem.material;
  spec.engine = dem.keys.engine;
  read_study_keys(root, "dem.patch_test", patch_test_keys(), spec);
  const bool unitless = is_unitless(spec.material);
  const double d_c = critical_diameter(spec.material);  // d_c = 4γE/σ_m,N² (6.35)

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
  const KeyTable<DemKeys>& dem_keys() const override {
    static const auto table =
        dem_table({.materials = "table-6.4 (Table 6.4, unitless), Si, SiO2 or a [materials.define] name",
                   .poisson_flag = "--nu",
                   .scaling_exponent_flag = "--s",
                   .cohesive_study = "patch test"});
    return table;
  }
  Schema study_keys() const override { return patch_test_keys().schema("dem.patch_test"); }
  void run(const Config& inputs, RunContext& context) override {
    const EngineRanks ranks(engine_);
    const auto outputs = run_patch_test_study(inputs, read_dem(inputs), context);
    require_elastic_bounds(context.results());
    finish(outputs, context, "");
  }
};

}  // namespace
}  // namespace wearscale::studies

WEARSCALE_STUDY(PatchTestStudy)
