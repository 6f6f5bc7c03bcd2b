// The strength-table study ([md]): shear strengths σ_max(p), σ_dyn(p) of a
// material with an interatomic model (Si, SiO2, or one the case defines in
// [materials.define.<name>.interatomic]) from the MD shear test of §9.3.1,
// after the elastic check of its sample, run with LAMMPS at each pressure
// (md::run_shear_study; identical inputs are read from the result cache),
// written as a strength table (materials/ format, .csv or .h5) into the
// output folder, with each point's strengths as headline figures. Under
// mpirun/srun the pressure points are spread over the ranks by the task farm
// (each point's LAMMPS on md.ranks ranks of its own), rank 0 writing the
// table, which equals the serial one.
//
//   [case]
//   study = "strength-table"        # `wearscale strength-table` names it itself
//   [md]
//   material = "Si"                 # "SiO2", or a [materials.define.<name>] name
//   pressures = ["0 GPa", "10 GPa"] # at least two
//   preset = "smoke"                # or "thesis"; every other [md] key overrides it
//   [output]
//   file = "si.csv"                 # the table's name in the output folder
#include <cmath>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/coupling/shear_farm.hpp"
#include "wearscale/coupling/shear_test_keys.hpp"
#include "wearscale/io/strength_table_file.hpp"
#include "wearscale/materials/strength_table.hpp"
#include "wearscale/md/shear_study.hpp"
#include "wearscale/io/key_table.hpp"
#include "wearscale/studies/study.hpp"

namespace wearscale::studies {

namespace {

// The study's own keys besides the shear test's [md] (coupling/shear_test_keys.hpp).
struct StrengthTableKeys {
  std::string backend = "lammps";
  std::string file;
  // Not a key: the file's default, from the shear test's preset and material.
  std::string default_file;
};

const KeyTable<StrengthTableKeys>& strength_table_keys() {
  using K = StrengthTableKeys;
  static const auto table =
      KeyTable<K>()
          .choice("md.backend", &K::backend, {"lammps"}, "molecular backend")
          .flag("--backend")
          .custom("output.file", "string", "a file name ending in .csv or .h5", "",
                  "the table's name in the output folder",
                  [](const Config& c, const std::string& key, K& k) {
                    k.file = output_file_name(c, key, k.default_file, {".csv", ".h5"});
                  })
          .fallback("lammps_<preset>_<material>.csv")
          .flag("--table");
  return table;
}

class StrengthTableStudy final : public Study {
 public:
  std::string name() const override { return "strength-table"; }
  std::string summary() const override {
    return "shear strengths σ_max(p), σ_dyn(p) of a material with an interatomic model (Si, SiO2, or "
           "[materials.define.<name>.interatomic]) from the MD shear test of §9.3.1 (LAMMPS), written as a strength "
           "table";
  }
  std::string default_case_name() const override { return "strength-table"; }
  Schema schema() const override;

  std::vector<std::string> prepare(Config& cfg) override {
    spec_ = coupling::read_shear_test_spec(cfg);
    if (spec_.pressures.size() < 2)
      throw cfg.error("md.pressures", "a strength table needs at least two pressures", "two or more pressures");
    StrengthTableKeys keys;
    keys.default_file = fmt::format("lammps_{}_{}.csv", spec_.preset, spec_.material);
    strength_table_keys().read(cfg, keys);
    file_ = keys.file;
    cfg.reject_unknown_keys();
    return {};
  }

  // Under mpirun: rank 0 runs the study (run), the other ranks take points from its farm.
  bool distributed() const override { return true; }
  bool has_ensembles() const override { return true; }
  void run_other_rank(const Config& /*inputs*/) override {
    (void)md::run_shear_study(spec_, coupling::farmed_shear_runs("strength-table points"));
  }

  void run(const Config& /*cfg*/, RunContext& context) override {
    const md::ShearStudy study = md::run_shear_study(spec_, coupling::farmed_shear_runs("strength-table points"));
    const materials::StrengthTable table = md::strength_table(study);
    const auto file = context.output_dir() / file_;
    materials::write_strength_table(file, table);
    context.add_file(file);
    for (std::size_t i = 0; i < table.pressure.size(); ++i) {
      const std::string at = fmt::format("at p = {:g} GPa", table.pressure[i] / 1e9);
      context.report(fmt::format("sigma_max_{}", i), table.sigma_max[i], "Pa", "maximum shear strength σ_max " + at);
      context.report(fmt::format("sigma_dyn_{}", i), table.sigma_dyn[i], "Pa", "dynamic shear strength σ_dyn " + at);
    }
    if (study.elastic) {
      const auto& e = *study.elastic;
      const bool iso = e.isotropic;
      context.report("sample_young", iso ? e.sample.young : e.sample.young_z, "Pa",
                     iso ? "Young's modulus of the sample at 0 K (isotropic)" : "Young's modulus E_z of the sample at 0 K");
      context.report("reference_young", iso ? e.reference.young : e.reference.young_z, "Pa",
                     "the same of the reference: " + e.reference_source);
      context.report("sample_poisson", iso ? e.sample.poisson : e.sample.poisson_zx, "1",
                     iso ? "Poisson's ratio of the sample at 0 K (isotropic)" : "Poisson's ratio ν_zx of the sample at 0 K");
      context.report("reference_poisson", iso ? e.reference.poisson : e.reference.poisson_zx, "1",
                     "the same of the reference");
      context.report("sample_shear_modulus", e.sample.shear_xz, "Pa", "shear modulus G_xz of the sample at 0 K");
    }
    for (std::size_t i = 0; i < study.points.size(); ++i)
      if (std::isfinite(study.points[i].shear_modulus))
        context.report(fmt::format("shear_modulus_{}", i), study.points[i].shear_modulus, "Pa",
                     fmt::format("elastic shear modulus from the start of the shear curve at p = {:g} GPa",
                                 study.points[i].pressure / 1e9));
    context.note("material", table.material);
    context.note("backend", "lammps");
    context.note("preset", spec_.preset);
    context.note("file", file.string());
    context.note("lammps_version", study.lammps_version);
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& p : study.points)
      rows.push_back({{"pressure_Pa", p.pressure},
                      {"sigma_max_Pa", p.strength.sigma_max},
                      {"sigma_dyn_Pa", p.strength.sigma_dyn},
                      {"strain_at_max", p.strength.strain_at_max},
                      {"sigma_dyn_std_Pa", p.strength.sigma_dyn_std},
                      {"temperature_window_K", p.strength.temperature_window},
                      {"cached", p.run.cached},
                      {"wall_seconds", p.run.wall_seconds}});
    context.note("rows", rows);
    nlohmann::json provenance = nlohmann::json::object();
    for (const auto& [k, v] : table.provenance) provenance[k] = v;
    context.note("table_provenance", provenance);
  }

 private:
  md::ShearTestSpec spec_;
  std::string file_;
};

Schema StrengthTableStudy::schema() const {
  Schema schema = strength_table_keys().schema();
  // The shear test's keys as its key table declares them, with the command's aliases.
  for (auto& k : coupling::md_schema()) {
    if (k.key == "md.material") k.flag = "--material";
    if (k.key == "md.pressures") {
      k.range += ", at least two";  // a table's (prepare)
      k.flag = "--pressures";
      k.list_unit = "GPa";
    }
    if (k.key == "md.preset") k.flag = "--preset";
    if (k.key == "md.lmp") k.flag = "--lmp";
    if (k.key == "md.ranks") k.flag = "--ranks";
    schema.push_back(std::move(k));
  }
  for (auto& k : material_schema()) schema.push_back(std::move(k));
  return schema;
}

}  // namespace
}  // namespace wearscale::studies

WEARSCALE_STUDY(StrengthTableStudy)
