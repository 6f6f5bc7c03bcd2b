// molecular/lammps: shear strengths σ_max(p), σ_dyn(p) computed by a real
// LAMMPS run of the §9.3.1 shear test for each material of the case (Si with
// Stillinger–Weber, SiO2 with Vashishta at r_c = 8 Å), cached by input so a
// sweep or a rerun does not recompute them.
#include <map>

#include "wearscale/coupling/scale.hpp"
#include "backends/case_materials.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/task_farm.hpp"
#include "wearscale/core/task_store.hpp"
#include "wearscale/coupling/shear_farm.hpp"
#include "wearscale/materials/strength_law.hpp"
#include "wearscale/md/shear_study.hpp"
#include "wearscale/coupling/shear_test_keys.hpp"

namespace wearscale::coupling {

namespace {

class MolecularLammps final : public Scale {
 public:
  explicit MolecularLammps(const ScaleSetup& setup) : provenance_(setup.provenance()) {
    const auto library = material_library(setup.root);
    for (const auto& m : case_materials(setup.root, library)) {
      if (m != "Si" && m != "SiO2")
        throw setup.section.error("backend", "the LAMMPS shear test knows Si and SiO2 only (material '" + m + "')",
                                  "\"table\" or \"ideal\" for other materials");
      specs_.emplace(m, read_shear_test_spec(setup.section, m));
      register_served_shear_study(m, specs_.at(m));  // under mpirun any rank may run its points
    }
    outside_ = setup.section.choice_or("outside", "error", {"error", "clamp"}) == "clamp"
                   ? materials::OutsideTable::Clamp
                   : materials::OutsideTable::Error;
  }

  std::vector<Key> consumes() const override { return {}; }
  std::vector<Key> provides() const override {
    std::vector<Key> out;
    for (const auto& [m, spec] : specs_) out.push_back({Quantity::ShearStrength, m});
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
      publish_strength(exchange, ctx, m, materials::StrengthLaw(md::strength_table(study), outside_), std::move(p));
    }
  }

 private:
  Provenance provenance_;
  std::map<std::string, md::ShearTestSpec> specs_;
  materials::OutsideTable outside_ = materials::OutsideTable::Error;
};

}  // namespace

WEARSCALE_BACKEND(molecular_lammps) {
  registry.add({"molecular", "lammps",
                "σ_max(p), σ_dyn(p) from live LAMMPS shear tests of Si (SW) and SiO2 (Vashishta) (§9.3.1), cached",
                {},
                {"ShearStrength(<each material of [materials]>)"}},
               [](const ScaleSetup& s) { return std::make_unique<MolecularLammps>(s); });
}

}  // namespace wearscale::coupling
