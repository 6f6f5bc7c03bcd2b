// molecular/lammps: shear strengths σ_max(p), σ_dyn(p) computed by a real
// LAMMPS run of the §9.3.1 shear test for each material of the case with an
// interatomic model (built in: Si with Stillinger–Weber, SiO2 with Vashishta
// at r_c = 8 Å; others from [materials.define.<name>.interatomic]), after the
// sample's elastic check, cached by input so a sweep or a rerun does not
// recompute them.
#include <cctype>
#include <map>

#include <fmt/format.h>

#include "wearscale/coupling/scale.hpp"
#include "backends/case_materials.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/task_farm.hpp"
#include "wearscale/core/task_store.hpp"
#include "wearscale/coupling/shear_farm.hpp"
#include "wearscale/materials/strength_law.hpp"
#include "wearscale/md/shear_study.hpp"
#include "wearscale/coupling/shear_test_keys.hpp"
#include "wearscale/io/strength_table_file.hpp"

namespace wearscale::coupling {

namespace {

// A material's name as a word of a file name: letters, digits, '-' and '_' kept, anything else '_'
// (the name is a key of the case: it must not lead out of the output folder).
std::string file_word(const std::string& name) {
  std::string out;
  for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
  return out;
}

class MolecularLammps final : public Scale {
 public:
  static inline const Ports ports{{}, {{Quantity::ShearStrength, "<each material of [materials]>"}}};

  explicit MolecularLammps(const ScaleSetup& setup) : provenance_(setup.provenance()) {
    const auto library = material_library(setup.root);
    // A case may keep both backends' keys: `data`/`tables` for molecular/table
    // and a [scale.molecular.lammps] table of this backend's keys (how its
    // tables were computed); `--set scale.molecular.backend=...` picks one.
    const bool both = setup.section.has("lammps");
    const Config keys = both ? setup.section.section("lammps") : setup.section;
    if (both) {
      setup.section.mark_used("data");
      setup.section.mark_used("tables");
    }
    for (const auto& m : case_materials(setup.root, library)) {
      const auto& record = library.get(m);
      if (!record.interatomic)
        throw setup.section.error(
            "backend", fmt::format("material '{}' has no interatomic model for the LAMMPS shear test", m),
            fmt::format("a [materials.define.{}.interatomic] table, or backend \"table\" or \"ideal\"", m));
      specs_.emplace(m, read_shear_test_spec(keys, m, *record.interatomic));
      register_served_shear_study(m, specs_.at(m));  // under mpirun any rank may run its points
    }
    StrengthLawKeys law;
    strength_law_keys().read(setup.section, law);
    outside_ = law.outside;
  }

  std::vector<Key> consumes() const override { return ports.consumes; }
  std::vector<Key> provides() const override {
    std::vector<Key> out;
    for (const auto& [m, spec] : specs_) out.push_back({ports.provides[0].what, m});
    return out;
  }

  // Under mpirun the runs (the SiO2 quench, then the points) go over the ranks.
  bool farms_ensembles() const override { return true; }

  void run(Exchange& exchange, RunContext& ctx) override {
    for (const auto& [m, spec] : specs_) {
      // Cached by every input; under mpirun (a served pipeline) each run on whichever rank asks.
      // A shard (--task K/N) or a merge takes its runs through the task farm too, one rank.
      const mpi::TaskStore* store = mpi::TaskStore::current();
      const bool farmed =
          mpi::ServedRun::active() || (store != nullptr && store->mode() != mpi::TaskStore::Mode::Keep);
      const auto study = md::run_shear_study(spec, farmed ? served_shear_runs(m, "molecular/lammps " + m) : md::RunMap{});
      Provenance p = provenance_;
      p.parameters["lammps_version"] = study.lammps_version;
      // The table as a file too (the project's CSV convention), for backend = "table" to read back.
      materials::StrengthTable table = md::strength_table(study);
      const auto file = ctx.output_dir() / fmt::format("strength_{}.csv", file_word(m));
      materials::write_strength_table(file, table);
      ctx.add_file(file);
      table.origin = file.string();
      publish_strength(exchange, ctx, m, materials::StrengthLaw(std::move(table), outside_), std::move(p));
    }
  }

 private:
  Provenance provenance_;
  std::map<std::string, md::ShearTestSpec> specs_;
  materials::OutsideTable outside_ = materials::OutsideTable::Error;
};

}  // namespace

namespace {

// The keys of [scale.molecular] with backend = "lammps": the shear test's
// (read by read_shear_test_spec, here or in a [scale.molecular.lammps] table)
// and the strength law's.
Schema lammps_keys() {
  const std::string prefix = "scale.molecular";
  Schema rows = strength_law_keys().schema(prefix);
  for (auto& row : shear_test_schema(prefix)) rows.push_back(std::move(row));
  rows.push_back({prefix + ".lammps", "table", "the keys above", "", "",
                  "the keys above in a table of their own, beside molecular/table's data and tables", ""});
  return rows;
}

}  // namespace

WEARSCALE_BACKEND(molecular_lammps) {
  registry.add<MolecularLammps>(
      "molecular", "lammps",
      "σ_max(p), σ_dyn(p) from live LAMMPS shear tests (§9.3.1) of each material with an interatomic model "
      "(Si: SW, SiO2: Vashishta, or [materials.define.<name>.interatomic]), cached",
      lammps_keys);
}

}  // namespace wearscale::coupling
