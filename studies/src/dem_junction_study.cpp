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

nlohmann::json run_junction_study(const Config& root, RunContext& context) {
  const std::filesystem::path& out = context.output_dir();
  Checkpointer* checkpoints = &context.checkpoints();
  ShearedJunctionSpec spec;
  spec.material = dem_material(root);
  require_cohesive_law(root, "junction study");
  spec.engine = read_engine(root);
  const Config c = root.section("dem.junction");
  spec.diameter = c.number("diameter", Range::positive(), units::length);
  spec.d0 = read_d0(c);
  spec.largest = read_largest(c, spec.d0);
  if (const auto box = read_box(c)) spec.box = *box;
  // Any velocity > 0: the junction's is not bounded as the sliding cell's (read_sliding_velocity).
  spec.velocity = c.number_or("velocity", 10.0, Range::positive(), units::velocity);
  // As the sliding cell's: beyond the material's normal strength σ_m,N the cohesive model no longer holds a
  // solid (a pressure of 1e15 Pa crushed the sample and reported no resistance to sliding).
  spec.pressure = read_pressure(c, 100e6, spec.material);
  spec.time_step = read_time_step(c);
  spec.sliding_distance = read_sliding_distance(c, 1.5 * spec.diameter);
  spec.seed = static_cast<unsigned>(read_seed(c));
  const long dump_every = read_dump_every(c, 2000);
  root.reject_unknown_keys();

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
  Schema schema() const override {
    const std::string t = "dem.junction";
    Schema s = material_keys({.materials = "Si, SiO2 or a [materials.define] name"});
    // The junction reads its own keys (not the sliding cell's): these.
    s.insert(s.end(),
             {{t + ".diameter", "number", "> 0", "m", "", "junction diameter D, e.g. 20e-9 or \"20 nm\"", "--D"},
              d0_key(t),
              {t + ".velocity", "number", "> 0", "m/s", "10", "sliding velocity of the top wall", "--velocity"},
              pressure_key(t, "1e8"),
              sliding_distance_key(t, "1.5 D"),
              seed_key(t),
              largest_key(t),
              box_key(t, "[60e-9, 40e-9, 40e-9]", "cell size [x, y, z]"),
              time_step_key(t),
              dump_every_key(t, 2000)});
    return s;
  }
  void run(const Config& inputs, RunContext& context) override {
    const EngineRanks ranks(engine_);
    finish(run_junction_study(inputs, context), context, "junction");
  }
};

}  // namespace
}  // namespace wearscale::studies

WEARSCALE_STUDY(JunctionStudy)
