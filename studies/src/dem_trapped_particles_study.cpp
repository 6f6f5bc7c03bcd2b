// The loose particles trapped between flat surfaces of §7.3 (`wearscale dem
// trapped-particles`, [dem.trapped_particles]): n discs of diameter D in a gap
// of height D, the top wall pressed and slid. The loose particles roll, or a
// shear band forms in the first bodies.
#include <filesystem>
#include <string>
#include <fmt/format.h>

#include "dem_case.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/dem/dump_writer.hpp"
#include "wearscale/dem/trapped_particles.hpp"
#include "wearscale/io/hdf5_file.hpp"

namespace wearscale::studies {

namespace {

using namespace dem;

// What [dem.trapped_particles] fills: the study's spec and its snapshots.
struct TrappedParticlesKeys {
  TrappedParticlesSpec spec;
  long dump_every = 2000;
};

const KeyTable<TrappedParticlesKeys>& trapped_particles_keys() {
  using K = TrappedParticlesKeys;
  const auto cell = [](auto& k) -> auto& { return k.spec.cell; };
  // The cell's height fits the gap D and both surfaces: walls and two more d0 each.
  const auto min_height = [](const K& k) {
    return k.spec.diameter + 2.0 * (k.spec.cell.wall_thickness + 2.0) * k.spec.cell.d0;
  };
  static const auto table = [&] {
    KeyTable<K> t;
    add_sliding_cell(t, cell);
    t.integer("count", [](K& k) -> int& { return k.spec.count; }, Range::closed(1, 16),
              "number of loose particles (thesis: 2 to 4)")
        .allowed("1 … 16")
        .flag("--n")
        .number("diameter", [](K& k) -> double& { return k.spec.diameter; }, Range::positive(), units::length,
                "diameter of the loose particles (= the gap)")
        .range_from([](const K& k) { return Range::at_least(3.0 * k.spec.cell.d0); }, "≥ 3 d0")
        .required()
        .flag("--D");
    add_clearance(t, [](K& k) -> double& { return k.spec.clearance; },
                  "clearance between the loose particles and the surfaces, in d0");
    t.number("fit_from", [](K& k) -> double& { return k.spec.fit_from; }, Range::closed_open(0.0, 1.0),
             "the rigid-body fit of the loose particles runs from this fraction of the slide")
        .number("length", [](K& k) -> double& { return k.spec.cell.box.x; }, Range::positive(), units::length,
                "cell length L")
        .range_from([](const K& k) { return Range::at_least(k.spec.count * (k.spec.diameter + k.spec.cell.d0)); },
                    "≥ n (D + d0)")
        .computed_default([](const K& k) { return 3.0 * k.spec.count * k.spec.diameter; }, "3 n D")
        .flag("--length");
    add_cell_depth(t, cell);
    t.number("height", [](K& k) -> double& { return k.spec.cell.box.z; }, Range::positive(), units::length,
             "cell height H")
        .range_from([min_height](const K& k) { return Range::at_least(min_height(k)); },
                    "≥ D + 2 (wall_thickness + 2) d0")
        .computed_default([min_height](const K& k) { return min_height(k) + 2.0 * k.spec.cell.d0; },
                          "D + 2 (wall_thickness + 3) d0");
    add_sliding_distance(t, [](K& k) -> double& { return k.spec.cell.sliding_distance; },
                         [](const K& k) { return k.spec.cell.box.x; }, "L");
    add_dump_every(t, &K::dump_every);
    return t;
  }();
  return table;
}

nlohmann::json run_trapped_particles_study(const Config& root, const DemInputs& dem, RunContext& context) {
  const std::filesystem::path& out = context.output_dir();
  Checkpointer* checkpoints = &context.checkpoints();
  TrappedParticlesKeys k;
  with_dem(dem, k.spec.cell);  // the pressure's range is the material's
  const Config c = read_study_keys(root, "dem.trapped_particles", trapped_particles_keys(), k);
  TrappedParticlesSpec& spec = k.spec;
  const double d0 = spec.cell.d0;
  const long dump_every = k.dump_every;

  log::info("DEM trapped particles (§7.3): {} n = {}, D = {:.3g} m, L = {:.3g} m, d0 = {:.3g} m, v = {:g} m/s, p = {:.3g} Pa",
            spec.cell.material.name, spec.count, spec.diameter, spec.cell.box.x, d0, spec.cell.velocity, spec.cell.pressure);
  std::filesystem::create_directories(out);
  SlidingDumps dumps{DumpWriter(out / "trapped_particles.dump"), dump_every, nullptr, spec.cell.record_every};
  const auto hooks = study_checkpoints(checkpoints, "dem/trapped_particles", &dumps.writer);
  const auto r = run_trapped_particles(
      spec,
      [&](const SlidingCell& cell, const SlidingSample&, long step, long planned) {
        dumps(cell, step, planned, "trapped particles", hooks);
      },
      hooks);
  dumps.bar.reset();
  dumps.writer.commit();

  H5Writer h5(out / "trapped_particles.h5");
  auto files = write_sliding_history(
      r.history, out / "trapped_particles_history.csv", h5,
      fmt::format("{} {} particles of D = {:.3g} m trapped between flat surfaces (§7.3), d0 = {:.3g} m, p_N = {:.3g} Pa; {}",
                  spec.count, spec.cell.material.name, spec.diameter, d0, spec.cell.pressure, r.regime()));
  h5.set_attribute("/", "case_toml", root.to_toml());
  auto put = [&](const std::string& name, double v, const std::string& unit, const std::string& what) {
    context.report(name, v, unit, what);
    h5.write_scalar("/results/" + name, v, unit);
  };
  double loose = 0.0;
  for (auto n : r.loose_particles) loose += static_cast<double>(n) / static_cast<double>(r.loose_particles.size());
  put("rolling", r.rolling ? 1.0 : 0.0, "1", r.regime());
  put("mean_residual", r.mean_residual, "1", "loose particles' motion not explained by rigid bodies (0: rigid)");
  put("friction", r.friction, "1", "mean F_T / mean F_N over the second half");
  put("mean_pressure", r.mean_pressure, "Pa", "mean measured p_N over the second half of the slide");
  put("pressure_ratio", spec.cell.pressure > 0.0 ? r.mean_pressure / spec.cell.pressure : 0.0, "1",
      "measured over imposed p_N (1: the wall holds the load)");
  put("mean_tangential_force", r.mean_tangential_force, "N", "mean F_T over the second half");
  put("peak_tangential_force", r.peak_tangential_force, "N", "peak F_T");
  put("worn_first_body", static_cast<double>(r.worn_first_body), "1", "worn particles of the two surfaces");
  put("band_thickness", r.band_thickness, "m", "first-body material worn: its volume / (φ L W)");
  put("loose_particles", loose, "1", "DEM particles per loose particle");
  put("d_star", r.d_star, "m", "critical junction size 32γG/σ_m,T² (6.65)");
  put("particles", static_cast<double>(r.particles), "1", "particles");
  put("steps", static_cast<double>(r.steps), "1", fmt::format("steps of Δt = {:.3g} s", r.time_step));
  h5.commit();
  files.push_back(dumps.writer.final_path().string());
  return {{"verdict", r.regime()},
          {"caption", fmt::format("{}, n = {} particles of D = {:.3g} nm, d_0 = {:.3g} nm, p_N = {:.3g} GPa",
                                  spec.cell.material.name, spec.count, spec.diameter * 1e9, d0 * 1e9,
                                  spec.cell.pressure / 1e9)},
          {"files", files}};
}

class TrappedParticlesStudy final : public DemStudy {
 public:
  std::string name() const override { return "dem/trapped_particles"; }
  std::string summary() const override {
    return "n loose particles sheared between flat surfaces (§7.3): rolling particles or a shear band";
  }
  const KeyTable<DemKeys>& dem_keys() const override {
    static const auto table =
        dem_table({.materials = "Si, SiO2 or a [materials.define] name", .history = true});
    return table;
  }
  Schema study_keys() const override { return trapped_particles_keys().schema("dem.trapped_particles"); }
  void run(const Config& inputs, RunContext& context) override {
    const EngineRanks ranks(engine_);
    finish(run_trapped_particles_study(inputs, read_dem(inputs), context), context, "trapped_particles");
  }
};


}  // namespace
}  // namespace wearscale::studies

WEARSCALE_STUDY(TrappedParticlesStudy)
