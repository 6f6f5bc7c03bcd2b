// molecular/table: shear strengths σ_max(p), σ_dyn(p) from tables — the
// shipped ones (thesis Fig. 9.18 laws, or wearscale's own LAMMPS runs) or a
// user's file per material (§9.3.1).
#include <map>

#include "wearscale/coupling/scale.hpp"
#include "wearscale/io/strength_table_file.hpp"
#include "backends/case_materials.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/io/shipped_data.hpp"
#include "wearscale/materials/strength_law.hpp"

namespace wearscale::coupling {

namespace {

class MolecularTable final : public Scale {
 public:
  static inline const Ports ports{{}, {{Quantity::ShearStrength, "<each material of [materials]>"}}};

  explicit MolecularTable(const ScaleSetup& setup) : provenance_(setup.provenance()) {
    const Config& c = setup.section;
    const auto library = material_library(setup.root);
    materials_ = case_materials(setup.root, library);
    const std::string set = c.choice_or("data", "thesis", {"thesis", "lammps"});
    const auto outside = c.choice_or("outside", "error", {"error", "clamp"}) == "clamp"
                             ? materials::OutsideTable::Clamp
                             : materials::OutsideTable::Error;
    for (const auto& m : materials_) {
      // A file given in [scale.molecular.tables] wins over the shipped set.
      const std::string key = "tables." + m;
      materials::StrengthTable table;
      if (c.has(key)) {
        try {
          table = materials::read_strength_table(c.path(key));  // relative to the case file
        } catch (const InputError& e) {
          throw c.error(key, e.what());  // name the case key that points at the bad table
        }
      } else {
        table = materials::shipped_table(set, m);
      }
      laws_.emplace(m, materials::StrengthLaw(std::move(table), outside));
    }
    c.mark_used("tables");  // entries for materials the case does not use are allowed
    c.mark_used("lammps");  // molecular/lammps' keys, kept beside (how the tables were computed)
  }

  std::vector<Key> consumes() const override { return ports.consumes; }
  std::vector<Key> provides() const override {
    std::vector<Key> out;
    for (const auto& m : materials_) out.push_back({ports.provides[0].what, m});
    return out;
  }

  void run(Exchange& exchange, RunContext& ctx) override {
    for (const auto& [m, law] : laws_) publish_strength(exchange, ctx, m, law, provenance_);
  }

 private:
  Provenance provenance_;
  std::vector<std::string> materials_;
  std::map<std::string, materials::StrengthLaw> laws_;
};

}  // namespace

WEARSCALE_BACKEND(molecular_table) {
  registry.add<MolecularTable>(
      "molecular", "table",
      "shear strengths σ_max(p), σ_dyn(p) from shipped (thesis Fig. 9.18, wearscale LAMMPS) or user tables");
}

}  // namespace wearscale::coupling
