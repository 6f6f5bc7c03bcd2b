// The sheared junction of §6.3 (`wearscale dem junction`, [dem.junction]):
// two amorphous surfaces linked by a cylindrical junction of diameter D, the
// top wall slid under a normal pressure. Below d* = 32γG/σ_m,T² (6.65) the
// junction deforms plastically, above it detaches into a rolling wear particle.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>
#include <fmt/format.h>

#include "dem_case.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/progress.hpp"
#include "wearscale/dem/dump_writer.hpp"
#include "wearscale/dem/engine.hpp"
#include "wearscale/dem/sheared_junction.hpp"
#include "wearscale/io/csv.hpp"
#include "wearscale/io/hdf5_file.hpp"

namespace wearscale::studies {

namespace {

using namespace dem;

// What [dem.junction] fills: the study's spec and its snapshots.
struct JunctionKeys {
  ShearedJunctionSpec spec;
  long dump_every = 2000;
};

const KeyTable<JunctionKeys>& junction_keys() {
  using K = JunctionKeys;
  using S = ShearedJunctionSpec;
  const auto at = [](auto member) { return [member](K& k) -> auto& { return k.spec.*member; }; };
  static const auto table = [&] {
    KeyTable<K> t;
    t.number("diameter", at(&S::diameter), Range::positive(), units::length,
             "junction diameter D, e.g. 20e-9 or \"20 nm\"")
        .required()
        .flag("--D");
    add_d0(t, at(&S::d0));
    add_largest(t, at(&S::largest), [](const K& k) { return k.spec.d0; });
    add_box(t, at(&S::box), S{}.box, "cell size [x, y, z]");
    // Any velocity > 0: the junction's is not bounded as the sliding cell's (add_sliding_velocity).
    t.number("velocity", at(&S::velocity), Range::positive(), units::velocity, "sliding velocity of the top wall")
        .flag("--velocity");
    // As the sliding cell's: beyond the material's normal strength σ_m,N the cohesive model no longer holds a
    // solid (a pressure of 1e15 Pa crushed the sample and reported no resistance to sliding).
    add_pressure(t, at(&S::pressure), [](const K& k) -> const CohesiveMaterial& { return k.spec.material; });
    add_time_step(t, at(&S::time_step));
    add_sliding_distance(t, at(&S::sliding_distance), [](const K& k) { return 1.5 * k.spec.diameter; }, "1.5 D");
    add_seed(t, at(&S::seed));
    add_dump_every(t, &K::dump_every);
    return t;
  }();
  return table;
}

nlohmann::json run_junction_study(const Config& root, const DemInputs& dem, RunContext& context) {
  const std::filesystem::path& out = context.output_dir();
  Checkpointer* checkpoints = &context.checkpoints();
  JunctionKeys k;
  k.spec.material = dem.material;
  k.spec.engine = dem.keys.engine;
  read_study_keys(root, "dem.junction", junction_keys(), k);
  const ShearedJunctionSpec& spec = k.spec;
  const long dump_every = k.dump_every;

  log::info("DEM sheared junction: {} D = {:.3g} m, d0 = {:.3g} m, v = {:g} m/s, p = {:.3g} Pa", spec.material.name,
            spec.diameter, spec.d0, spec.velocity, spec.pressure);
  std::filesystem::create_directories(out);
  DumpWriter dump(out / "junction.dump");
  std::unique_ptr<Progress> bar;
  const auto hooks = study_checkpoints(checkpoints, "dem/junction", &dump);
  const auto r = run_sheared_junction(
      spec,
      [&](const Engine& sim, const JunctionSample&, long step, long planned) {
        if (!bar) bar = progress_bar("sheared junction", planned, hooks);
        if (dump.frames() == 0) dump.write(sim);
        bar->update(static_cast<double>(step));
        if (dump_every > 0 && (step % dump_every < spec.record_every || step == planned)) dump.write(sim);
      },
      hooks);
  bar.reset();
  dump.commit();

  std::vector<double> t, s, ft, fn, ke;
  for (const auto& h : r.history) {
    t.push_back(h.time);
    s.push_back(h.sliding);
    ft.push_back(h.tangential_force);
    fn.push_back(h.normal_force);
    ke.push_back(h.kinetic_energy);
  }
  const auto csv = out / "junction_history.csv";
  write_csv(csv, {"time", "sliding", "tangential_force", "normal_force", "kinetic_energy"}, {t, s, ft, fn, ke},
            {"s", "m", "N", "N", "J"},
            {fmt::format("sheared {} junction (§6.3): D = {:.3g} m, d0 = {:.3g} m; {}", spec.material.name,
                         spec.diameter, spec.d0, r.verdict())});
  const auto h5_path = out / "junction.h5";
  H5Writer h5(h5_path);
  h5.write_table("/history", {"time", "sliding", "tangential_force", "normal_force", "kinetic_energy"}, {t, s, ft, fn, ke},
                 {"s", "m", "N", "N", "J"});
  h5.set_attribute("/", "case_toml", root.to_toml());
  auto put = [&](const std::string& name, double v, const std::string& unit, const std::string& what) {
    context.report(name, v, unit, what);
    h5.write_scalar("/results/" + name, v, unit);
  };
  put("detached", r.detached ? 1.0 : 0.0, "1", r.verdict());
  put("d_star", r.d_star, "m", "critical junction size 32γG/σ_m,T² (6.65)");
  put("peak_tangential_force", r.peak_tangential_force, "N", "peak resistance to sliding");
  put("detached_cluster", static_cast<double>(r.detached_cluster), "1",
      fmt::format("particles of the largest free cluster (junction: {})", r.junction_particles));
  put("detached_diameter", r.detached_diameter, "m", "its equivalent diameter");
  put("rigid_residual", r.rigid_residual, "1", "junction motion not explained by a rigid body (0: rigid)");
  put("rolling_rate", r.rolling_rate, "1", "junction rotation about y in v/D (≈1 when rolling)");
  put("particles", static_cast<double>(r.particles), "1", "particles");
  put("steps", static_cast<double>(r.steps), "1", fmt::format("steps of Δt = {:.3g} s", r.time_step));
  h5.commit();
  return {{"verdict", r.verdict()},
          {"caption", fmt::format("{}, D = {:.3g} nm, d_0 = {:.3g} nm, p_N = {:.3g} GPa", spec.material.name,
                                  spec.diameter * 1e9, spec.d0 * 1e9, spec.pressure / 1e9)},
          {"files", {csv.string(), h5_path.string(), dump.final_path().string()}}};
}

class JunctionStudy final : public DemStudy {
 public:
  std::string name() const override { return "dem/junction"; }
  std::string summary() const override {
    return "a cylindrical junction sheared between two surfaces (§6.3): plastic deformation or a rolling wear particle";
  }
  const KeyTable<DemKeys>& dem_keys() const override {
    static const auto table =
        dem_table({.materials = "Si, SiO2 or a [materials.define] name", .cohesive_study = "junction study"});
    return table;
  }
  Schema study_keys() const override { return junction_keys().schema("dem.junction"); }
  void run(const Config& inputs, RunContext& context) override {
    const EngineRanks ranks(engine_);
    finish(run_junction_study(inputs, read_dem(inputs), context), context, "junction");
  }
};

}  // namespace
}  // namespace wearscale::studies

WEARSCALE_STUDY(JunctionStudy)
