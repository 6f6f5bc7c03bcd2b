// The sheared rough surfaces of §7.2 (`wearscale dem rough-shear`,
// [dem.rough_shear]): two amorphous surfaces of self-affine roughness carved
// from one relaxed box, the top wall pressed and slid. The force history, the
// worn particles and the roughness Sa of both surfaces as they wear.
#include <filesystem>
#include <string>
#include <string_view>
#include <fmt/format.h>

#include "dem_case.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/dem/dump_writer.hpp"
#include "wearscale/dem/rough_shear.hpp"
#include "wearscale/io/hdf5_file.hpp"

namespace wearscale::studies {

namespace {

using namespace dem;

// What [dem.rough_shear] fills: the study's spec and its snapshots.
struct RoughShearKeys {
  RoughShearSpec spec;
  long dump_every = 2000;
};

const KeyTable<RoughShearKeys>& rough_shear_keys() {
  using K = RoughShearKeys;
  const auto cell = [](auto& k) -> auto& { return k.spec.cell; };
  static const auto table = [&] {
    KeyTable<K> t;
    add_sliding_cell(t, cell);
    t.number("length", [](K& k) -> double& { return k.spec.cell.box.x; }, Range::positive(), units::length,
             "cell length L (thesis: 25, 50, 100 d0)")
        .range_from([](const K& k) { return Range::at_least(10.0 * k.spec.cell.d0); }, "≥ 10 d0")
        .computed_default([](const K& k) { return 25.0 * k.spec.cell.d0; }, "25 d0")
        .flag("--length");
    add_cell_depth(t, cell);
    t.number("height", [](K& k) -> double& { return k.spec.cell.box.z; }, Range::positive(), units::length,
             "cell height H")
        .range_from([](const K& k) { return Range::at_least(2.0 * (k.spec.cell.wall_thickness + 2.0) * k.spec.cell.d0); },
                    "≥ 2 (wall_thickness + 2) d0")
        .computed_default([](const K& k) { return 14.0 * k.spec.cell.d0; }, "14 d0")
        .number("roughness", [](K& k) -> double& { return k.spec.roughness; }, Range::closed(0.0, 0.1),
                "initial Sa / L (thesis: 0.01, 0.02, 0.04)")
        .flag("--roughness")
        .number("hurst", [](K& k) -> double& { return k.spec.hurst; }, Range::open_closed(0.0, 1.0),
                "Hurst exponent of the initial surfaces")
        .number("shortest_wavelength", [](K& k) -> double& { return k.spec.shortest_wavelength; }, Range::at_least(2.0),
                "shortest wavelength of the initial surfaces in d0");
    add_sliding_distance(t, [](K& k) -> double& { return k.spec.cell.sliding_distance; },
                         [](const K& k) { return k.spec.cell.box.x; }, "L");
    add_dump_every(t, &K::dump_every);
    return t;
  }();
  return table;
}

nlohmann::json run_rough_shear_study(const Config& root, const DemInputs& dem, RunContext& context) {
  const std::filesystem::path& out = context.output_dir();
  Checkpointer* checkpoints = &context.checkpoints();
  RoughShearKeys k;
  with_dem(dem, k.spec.cell);  // the pressure's range is the material's
  const Config c = read_study_keys(root, "dem.rough_shear", rough_shear_keys(), k);
  RoughShearSpec& spec = k.spec;
  const double d0 = spec.cell.d0;
  const long dump_every = k.dump_every;

  log::info("DEM sheared rough surfaces (§7.2): {} L = {:.3g} m, Sa = {:g} L, d0 = {:.3g} m, v = {:g} m/s, p = {:.3g} Pa",
            spec.cell.material.name, spec.cell.box.x, spec.roughness, d0, spec.cell.velocity, spec.cell.pressure);
  std::filesystem::create_directories(out);
  SlidingDumps dumps{DumpWriter(out / "rough_shear.dump"), dump_every, nullptr, spec.cell.record_every};
  const auto hooks = study_checkpoints(checkpoints, "dem/rough_shear", &dumps.writer);
  RoughShearResult r;
  try {
    r = run_rough_shear(
        spec,
        [&](const SlidingCell& cell, const SlidingSample&, long step, long planned) {
          dumps(cell, step, planned, "sheared rough surfaces", hooks);
        },
        hooks);
  } catch (const InputError& e) {  // the profiles need more height than given: name the key
    if (std::string_view(e.what()).find("cell height") == std::string_view::npos) throw;
    throw c.error("height", e.what());
  }
  dumps.bar.reset();
  dumps.writer.commit();

  const auto& first = r.history.front();
  const auto& last = r.history.back();
  const double sa_initial = 0.5 * (first.roughness_bottom + first.roughness_top);
  const double sa_final = 0.5 * (last.roughness_bottom + last.roughness_top);
  H5Writer h5(out / "rough_shear.h5");
  auto files = write_sliding_history(
      r.history, out / "rough_shear_history.csv", h5,
      fmt::format("sheared rough {} surfaces (§7.2): L = {:.3g} m, Sa = {:g} L, d0 = {:.3g} m, p_N = {:.3g} Pa; {}",
                  spec.cell.material.name, spec.cell.box.x, spec.roughness, d0, spec.cell.pressure, r.regime));
  h5.set_attribute("/", "case_toml", root.to_toml());
  auto put = [&](const std::string& name, double v, const std::string& unit, const std::string& what) {
    context.report(name, v, unit, what);
    h5.write_scalar("/results/" + name, v, unit);
  };
  put("mean_pressure", r.mean_pressure, "Pa", "mean measured p_N over the second half of the slide");
  put("pressure_ratio", spec.cell.pressure > 0.0 ? r.mean_pressure / spec.cell.pressure : 0.0, "1",
      "measured over imposed p_N (1: the wall holds the load)");
  put("friction", r.friction, "1", "mean F_T / mean F_N over the second half");
  put("mean_tangential_force", r.mean_tangential_force, "N", "mean F_T over the second half");
  put("peak_tangential_force", r.peak_tangential_force, "N", "peak F_T");
  put("worn", static_cast<double>(r.worn), "1", "worn particles at the end (> half of the initial neighbours lost)");
  put("worn_fraction", r.worn_fraction, "1", "of the mobile particles");
  put("imposed_roughness", r.imposed_roughness, "m", "Sa of the carved profiles");
  put("initial_roughness", sa_initial, "m", "measured Sa of the surfaces before sliding (mean of both)");
  put("final_roughness", sa_final, "m", "measured Sa at the end (unworn particles, mean of both)");
  put("roughness_ratio", sa_initial > 0.0 ? sa_final / sa_initial : 0.0, "1", "final over initial Sa");
  put("wear_particle", static_cast<double>(r.wear_particle), "1", "particles of the largest cluster of worn particles");
  put("wear_particle_residual", r.wear_particle_residual, "1", "its motion not explained by a rigid body (0: rigid)");
  put("rolling", r.regime == "rolling wear particles" ? 1.0 : 0.0, "1", r.regime);
  put("d_star", r.d_star, "m", "critical junction size 32γG/σ_m,T² (6.65)");
  put("particles", static_cast<double>(r.particles), "1", "particles");
  put("steps", static_cast<double>(r.steps), "1", fmt::format("steps of Δt = {:.3g} s", r.time_step));
  h5.commit();
  files.push_back(dumps.writer.final_path().string());
  return {{"verdict", r.regime},
          {"caption", fmt::format("{}, L = {:.3g} nm, Sa/L = {:g}, d_0 = {:.3g} nm, p_N = {:.3g} GPa",
                                  spec.cell.material.name, spec.cell.box.x * 1e9, spec.roughness, d0 * 1e9,
                                  spec.cell.pressure / 1e9)},
          {"files", files}};
}

class RoughShearStudy final : public DemStudy {
 public:
  std::string name() const override { return "dem/rough_shear"; }
  std::string summary() const override {
    return "two rough surfaces sheared under a normal pressure (§7.2): worn particles, F_T history, Sa evolution";
  }
  const KeyTable<DemKeys>& dem_keys() const override {
    static const auto table =
        dem_table({.materials = "Si, SiO2 or a [materials.define] name", .history = true});
    return table;
  }
  Schema study_keys() const override { return rough_shear_keys().schema("dem.rough_shear"); }
  void run(const Config& inputs, RunContext& context) override {
    const EngineRanks ranks(engine_);
    finish(run_rough_shear_study(inputs, read_dem(inputs), context), context, "rough_shear");
  }
};

}  // namespace
}  // namespace wearscale::studies

WEARSCALE_STUDY(RoughShearStudy)
