// molecular/table: shear strengths σ_max(p), σ_dyn(p) from tables — the
// shipped ones (thesis Fig. 9.18 laws, or wearscale's own LAMMPS runs) or a
// user's file per material (§9.3.1).
#include <map>

#include "wearscale/coupling/scale.hpp"
#include "wearscale/io/key_table.hpp"
#include "wearscale/io/strength_table_file.hpp"
#include "backends/case_materials.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/io/shipped_data.hpp"
#include "wearscale/materials/strength_law.hpp"

namespace wearscale::coupling {

namespace {

// The keys of [scale.molecular] with backend = "table".
struct StrengthTableKeys {
  std::string data = "thesis";
  StrengthLawKeys law;
  std::vector<std::string> materials;  ///< not a key: the case's materials, each one table
  std::map<std::string, materials::StrengthTable> tables;
};

// A file given in [scale.molecular.tables] wins over the shipped set.
void read_tables(const Config& c, StrengthTableKeys& k) {
  for (const auto& m : k.materials) {
    const std::string key = "tables." + m;
    materials::StrengthTable table;
    if (c.has(key)) {
      try {
        table = materials::read_strength_table(c.path(key));  // relative to the case file
      } catch (const InputError& e) {
        throw c.error(key, e.what());  // name the case key that points at the bad table
      }
    } else {
      table = materials::shipped_table(k.data, m);
    }
    k.tables.emplace(m, std::move(table));
  }
  c.mark_used("tables");  // entries for materials the case does not use are allowed
}

const KeyTable<StrengthTableKeys>& strength_table_keys() {
  using K = StrengthTableKeys;
  static const auto table =
      KeyTable<K>()
          .choice("data", &K::data, std::vector<std::string>{"thesis", "lammps"},
                  "shipped strength tables: the thesis' (Fig. 9.18 laws) or wearscale's own LAMMPS runs")
          .then([](const Config& c, K& k) { strength_law_keys().read(c, k.law); })
          .table("tables", "a strength table file per material: tables.<material> = \"file.csv\"", read_tables,
                 "file names relative to the case file")
          // molecular/lammps' keys, kept beside (how the tables were computed)
          .table("lammps", "the molecular/lammps keys the tables were computed with (kept, not read)",
                 [](const Config& c, K&) { c.mark_used("lammps"); });
  return table;
}

class MolecularTable final : public Scale {
 public:
  static inline const Ports ports{{}, {{Quantity::ShearStrength, "<each material of [materials]>"}}};

  explicit MolecularTable(const ScaleSetup& setup) : provenance_(setup.provenance()) {
    const auto library = material_library(setup.root);
    StrengthTableKeys k;
    k.materials = case_materials(setup.root, library);
    strength_table_keys().read(setup.section, k);
    materials_ = k.materials;
    for (auto& [m, table] : k.tables) laws_.emplace(m, materials::StrengthLaw(std::move(table), k.law.outside));
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
      "shear strengths σ_max(p), σ_dyn(p) from shipped (thesis Fig. 9.18, wearscale LAMMPS) or user tables", [] {
        Schema rows = strength_table_keys().schema("scale.molecular");
        for (auto& row : strength_law_keys().schema("scale.molecular")) rows.insert(rows.begin() + 1, std::move(row));
        return rows;
      });
}

}  // namespace wearscale::coupling
