// molecular/ideal: pressure-independent strengths equal to the ideal shear
// strength σ_m,T of each material record (Table 2.1): σ_max = σ_dyn = σ_m,T.
#include <map>

#include "wearscale/coupling/scale.hpp"
#include "backends/case_materials.hpp"
#include "wearscale/materials/strength_law.hpp"

namespace wearscale::coupling {

namespace {

class MolecularIdeal final : public Scale {
 public:
  static inline const Ports ports{{}, {{Quantity::ShearStrength, "<each material of [materials]>"}}};

  explicit MolecularIdeal(const ScaleSetup& setup) : provenance_(setup.provenance()) {
    const auto library = material_library(setup.root);
    for (const auto& m : case_materials(setup.root, library)) {
      const auto& record = library.get(m);
      laws_.emplace(m, materials::StrengthLaw::constant(m, record.shear_strength, 1e12,
                                                        "ideal shear strength of " + record.source));
    }
  }

  std::vector<Key> consumes() const override { return ports.consumes; }
  std::vector<Key> provides() const override {
    std::vector<Key> out;
    for (const auto& [m, law] : laws_) out.push_back({ports.provides[0].what, m});
    return out;
  }

  void run(Exchange& exchange, RunContext&) override {
    for (const auto& [m, law] : laws_) exchange.put<Quantity::ShearStrength>(m, law, provenance_);
  }

 private:
  Provenance provenance_;
  std::map<std::string, materials::StrengthLaw> laws_;
};

}  // namespace

WEARSCALE_BACKEND(molecular_ideal) {
  registry.add<MolecularIdeal>("molecular", "ideal",
                                "pressure-independent strengths σ_max = σ_dyn = σ_m,T (Table 2.1 records)",
                                [] { return Schema{}; });  // reads [materials] only
}

}  // namespace wearscale::coupling
