// The oxidized asperity of §9.3.3, Fig. 9.26 (`wearscale dem oxide-asperity`,
// [dem.oxide_asperity]): a loose SiO2 cylinder on an amorphous SiO2 layer over
// crystalline Si (HCP), rolled by a rigid plate pressed and slid over it. The
// cylinder picks up particles as it rolls and digs a trench towards the Si.
#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>
#include <fmt/format.h>

#include "dem_case.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/progress.hpp"
#include "wearscale/dem/dump_writer.hpp"
#include "wearscale/dem/engine.hpp"
#include "wearscale/dem/oxide_asperity.hpp"
#include "wearscale/io/csv.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/io/material_definitions.hpp"
#include "wearscale/materials/material.hpp"

namespace wearscale::studies {

namespace {

using namespace dem;

// [dem] material's default: the oxide of the layer, the cylinder and the plate.
constexpr const char* oxide_default = "SiO2";

// The substrate of the oxide-asperity study: a material of the library (or
// [materials.define]) by name, its ν at most the pair force's (6.52) and its η
// from the record or the key.
CohesiveMaterial substrate_material(const Config& root, const Config& c, double scaling_exponent) {
  const std::string name = c.string_or("substrate", "Si");
  materials::MaterialLibrary library;
  define_materials_from(library, root);
  if (!library.contains(name)) {
    std::string known;
    for (const auto& n : library.names()) known += (known.empty() ? "" : ", ") + n;
    throw c.error("substrate", fmt::format("unknown material '{}'", name), known);
  }
  const auto& record = library.get(name);
  const double eta = c.number_or("substrate_restitution", record.restitution ? *record.restitution : 0.9,
                                 Range{0.0, 1.0, true, false});
  CohesiveMaterial m = cohesive_material(record, scaling_exponent, eta);
  m.poisson = c.number_or("substrate_poisson", std::min(m.poisson, 0.2), Range::open_closed(-1.0, 0.25));
  require_modelled(m);
  return m;
}

// The SiO2–Si pairs: mix() of the two, with its adhesion energy and
// strengths replaced by the keys given.
CohesiveMaterial interface_material(const Config& c, const CohesiveMaterial& oxide, const CohesiveMaterial& substrate) {
  CohesiveMaterial m = mix(oxide, substrate);
  m.surface_energy = c.number_or("interface_surface_energy", m.surface_energy, Range::positive(), units::surface_energy);
  m.tensile_strength = c.number_or("interface_tensile_strength", m.tensile_strength, Range::positive(), units::pressure);
  m.shear_strength = c.number_or("interface_shear_strength", m.shear_strength, Range::positive(), units::pressure);
  return m;
}

nlohmann::json run_oxide_asperity_study(const Config& root, RunContext& context) {
  const std::filesystem::path& out = context.output_dir();
  require_cohesive_law(root, "oxide-asperity study");
  OxideAsperitySpec spec;
  spec.oxide = dem_material(root, oxide_default);
  spec.engine = read_engine(root);
  const Config c = root.section("dem.oxide_asperity");
  spec.substrate = substrate_material(root, c, spec.oxide.scaling_exponent);
  spec.interface = interface_material(c, spec.oxide, spec.substrate);
  spec.d0 = c.number_or("d0", 1.5e-9, Range::positive(), units::length);
  spec.largest = read_largest(c, spec.d0);
  if (const auto box = read_box(c)) spec.box = *box;
  spec.layer_thickness = c.number_or("layer_thickness", 5e-9, Range::at_least(0.5 * spec.d0), units::length);
  spec.body_diameter = c.number_or("body_diameter", 50e-9, Range::at_least(3.0 * spec.d0), units::length);
  spec.clearance = read_clearance(c);
  spec.plate_thickness = c.number_or("plate_thickness", 1.5, Range::closed(1.0, 10.0));
  spec.wall_thickness = read_wall_thickness(c);
  spec.velocity = read_sliding_velocity(c);
  spec.pressure = read_pressure(c, 100e6, spec.oxide);
  spec.time_step = read_time_step(c);
  spec.sliding_distance = read_sliding_distance(c, spec.box.x);
  spec.settle_distance = c.number_or("settle_distance", 2.0 * spec.d0, Range::positive(), units::length);
  spec.settle_damping = c.number_or("settle_damping", 0.1, Range::closed(0.0, 1.0));
  spec.track_distance = c.number_or("track_distance", 2.0 * spec.d0, Range::at_least(spec.d0), units::length);
  spec.record_every = read_record_every(c);
  spec.seed = read_seed(c);
  spec.relax_tolerance = read_relax_tolerance(c);
  spec.max_relax_steps = read_max_relax_steps(c);
  const long dump_every = read_dump_every(c, 5000);
  root.reject_unknown_keys();
  try {
    check(spec);
  } catch (const InputError& e) {  // name the key of the quantity refused
    const std::string_view what = e.what();
    for (const auto& [phrase, key] : {std::pair{"box", "box"}, {"settle distance", "settle_distance"},
                                      {"body diameter", "body_diameter"}, {"layer thickness", "layer_thickness"}})
      if (what.find(phrase) != std::string_view::npos) throw c.error(key, e.what());
    throw;
  }

  log::info("DEM oxidized asperity (§9.3.3): {} layer {:.3g} m and cylinder D = {:.3g} m on {} (HCP), box {:.3g} × {:.3g} "
            "× {:.3g} m, d0 = {:.3g} m, v = {:g} m/s, p = {:.3g} Pa",
            spec.oxide.name, spec.layer_thickness, spec.body_diameter, spec.substrate.name, spec.box.x, spec.box.y,
            spec.box.z, spec.d0, spec.velocity, spec.pressure);
  std::filesystem::create_directories(out);
  DumpWriter dump(out / "oxide_asperity.dump");
  std::unique_ptr<Progress> bar;
  const auto hooks = study_checkpoints(&context.checkpoints(), "dem/oxide_asperity", &dump);
  // A line in the log every 10 % of the run, 1 % for runs of more than 1e10
  // particle-steps (hours), and at least every 5 minutes: a long run's partial
  // results and its speed, particle-steps per CPU second of this process
  // since its first sample.
  std::clock_t cpu0 = 0;
  long step0 = 0, logged = 0;
  auto last_line = std::chrono::steady_clock::now();
  const auto r = run_oxide_asperity(
      spec, [&](const Engine& sim, const OxideAsperitySample& s, long step, long planned, const std::vector<double>& body) {
        if (!bar) {
          bar = progress_bar("oxidized asperity", planned, hooks);
          log::info("oxide asperity: {} particles, Δt = {:.3g} s, {} steps", sim.particles().size(), sim.time_step(), planned);
          cpu0 = std::clock();
          step0 = step;
        }
        bar->update(static_cast<double>(step));
        const long per = static_cast<double>(planned) * static_cast<double>(sim.particles().size()) > 1e10 ? 100 : 10;
        const auto now = std::chrono::steady_clock::now();
        if (step * per / planned > logged || step == planned || now - last_line > std::chrono::minutes(5)) {
          logged = step * per / planned;
          last_line = now;
          const double cpu = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
          // No speed on the first line (of a run, or of a resumed one): nothing measured yet.
          const std::string speed =
              step > step0 && cpu > 0.0
                  ? fmt::format("{:.3g} particle-steps per CPU s",
                                static_cast<double>(step - step0) * static_cast<double>(sim.particles().size()) / cpu)
                  : std::string("speed from the next line on");
          log::info("oxide asperity: step {}/{}, slide {:.4g} nm, F_T {:.4g} N, F_N {:.4g} N, body {} ({} picked up), "
                    "rotation {:.4g} rad, travel {:.4g} nm, trench {:.3g} nm (deepest {:.3g}); {}",
                    step, planned, s.sliding * 1e9, s.tangential_force, s.normal_force, s.body_particles, s.picked_up,
                    s.rotation, s.travel * 1e9, s.trench_depth * 1e9, s.trench_max_depth * 1e9, speed);
        }
        if (dump.frames() == 0 || (dump_every > 0 && (step % dump_every < spec.record_every || step == planned)))
          dump.write(sim, {{"rolling_body", body}});
      },
      hooks);
  bar.reset();
  dump.commit();

  const std::vector<std::string> names = {"time",          "sliding",   "tangential_force", "normal_force",
                                          "kinetic_energy", "body_particles", "picked_up", "rotation",
                                          "travel",         "trench_depth", "trench_max_depth"},
                                 unit = {"s", "m", "N", "N", "J", "1", "1", "rad", "m", "m", "m"};
  std::vector<std::vector<double>> cols(names.size());
  for (const auto& h : r.history) {
    const double row[] = {h.time,           h.sliding,   h.tangential_force, h.normal_force, h.kinetic_energy,
                          h.body_particles, h.picked_up, h.rotation,         h.travel,       h.trench_depth,
                          h.trench_max_depth};
    for (std::size_t k = 0; k < names.size(); ++k) cols[k].push_back(row[k]);
  }
  const std::vector<std::span<const double>> spans(cols.begin(), cols.end());
  const bool reached = r.reached_substrate_at >= 0.0;
  const std::string verdict =
      fmt::format("body {} rolling (ratio {:.2f}), {} → {} particles, trench {:.2g} nm{}",
                  r.rolling_ratio > 0.5 ? "is" : "is not", r.rolling_ratio, r.body_particles, r.final_body,
                  r.trench_depth * 1e9, reached ? ", reached the Si" : "");
  const auto csv = out / "oxide_asperity_history.csv";
  write_csv(csv, names, spans, unit,
            {fmt::format("oxidized asperity (§9.3.3): {} cylinder D = {:.3g} m on a {:.3g} m {} layer over HCP {}, d0 = {:.3g} "
                         "m, p_N = {:.3g} Pa; {}",
                         spec.oxide.name, spec.body_diameter, spec.layer_thickness, spec.oxide.name, spec.substrate.name,
                         spec.d0, spec.pressure, verdict)});
  H5Writer h5(out / "oxide_asperity.h5");
  h5.write_table("/history", names, spans, unit);
  h5.set_attribute("/", "case_toml", root.to_toml());
  auto put = [&](const std::string& name, double v, const std::string& u, const std::string& what) {
    context.report(name, v, u, what);
    h5.write_scalar("/results/" + name, v, u);
  };
  put("particles", static_cast<double>(r.particles), "1", "particles");
  put("substrate_particles", static_cast<double>(r.substrate_particles), "1", "Si particles (HCP)");
  put("layer_particles", static_cast<double>(r.layer_particles), "1", "SiO2 layer particles");
  put("body_initial", static_cast<double>(r.body_particles), "1", "particles of the loose cylinder as built");
  put("plate_particles", static_cast<double>(r.plate_particles), "1", "particles of the rigid plate");
  put("box_x", r.box.x, "m", "periodic length along x (whole HCP cells)");
  put("box_y", r.box.y, "m", "periodic length along y (whole HCP cells)");
  put("relax_scale", r.relax_scale, "1", "scale of the relaxed SiO2 onto the lattice's lengths");
  put("relax_strain", r.relax_strain, "1", "in-plane strain left after that scale");
  put("layer_measured", r.layer_measured, "m", "layer surface over the Si surface before sliding");
  put("body_final", r.final_body, "1", "particles of the rolling body at the end");
  put("picked_up", r.final_picked_up, "1", "of those, taken from the layer or the Si");
  put("rotation", r.rotation, "rad", "body rotation about y over the slide");
  put("travel", r.travel, "m", "body centre travel along x");
  put("rolling_ratio", r.rolling_ratio, "1", "|rotation| R / travel (1: rolling without slip)");
  put("trench_depth", r.trench_depth, "m", "mean depth of the strip passed, below the initial surface");
  put("trench_max_depth", r.trench_max_depth, "m", "deepest bin of that strip");
  put("reached_substrate_at", r.reached_substrate_at, "m", "slide at which the trench reached the Si (−1: not)");
  put("friction", r.friction, "1", "mean F_T / mean F_N over the second half");
  put("mean_tangential_force", r.mean_tangential_force, "N", "mean F_T over the second half");
  put("steps", static_cast<double>(r.steps), "1", fmt::format("steps of Δt = {:.3g} s", r.time_step));
  put("relaxation_steps", static_cast<double>(r.relaxation_steps), "1", "steps relaxing the SiO2 (§6.2.2)");
  h5.commit();
  return {{"verdict", verdict},
          {"caption", fmt::format("{} cylinder D = {:.3g} nm on {:.3g} nm {} over {}, d_0 = {:.3g} nm, p_N = {:.3g} MPa",
                                  spec.oxide.name, spec.body_diameter * 1e9, spec.layer_thickness * 1e9, spec.oxide.name,
                                  spec.substrate.name, spec.d0 * 1e9, spec.pressure / 1e6)},
          {"files", {csv.string(), h5.final_path().string(), dump.final_path().string()}}};
}

class OxideAsperityStudy final : public DemStudy {
 public:
  std::string name() const override { return "dem/oxide_asperity"; }
  std::string summary() const override {
    return "a loose SiO2 cylinder rolled by a plate on an oxidized Si surface (§9.3.3, Fig. 9.26): growth, trench";
  }
  Schema schema() const override {
    const std::string t = "dem.oxide_asperity";
    Schema s = material_keys({.materials = "the oxide (layer, cylinder, plate): SiO2 or a [materials.define] name",
                              .fallback = oxide_default});
    s.insert(s.end(),
             {{t + ".substrate", "string", "", "", "Si", "the HCP substrate's material (library or [materials.define] name)", ""},
              {t + ".substrate_poisson", "number", "(-1, 0.25]", "1", "min(ν, 0.2)",
               "the substrate's modelled ν (Si's 0.27 exceeds the pair force's 1/4 (6.52))", ""},
              {t + ".substrate_restitution", "number", "(0, 1]", "1", "record or 0.9", "the substrate's η", ""},
              {t + ".interface_surface_energy", "number", "> 0", "J/m^2", "√(γ_oxide γ_substrate)",
               "adhesion energy γ of the oxide–substrate pairs (the Si/SiO2 interface)", ""},
              {t + ".interface_tensile_strength", "number", "> 0", "Pa", "the weaker σ_m,N",
               "σ_m,N of the oxide–substrate pairs", ""},
              {t + ".interface_shear_strength", "number", "> 0", "Pa", "the weaker σ_m,T",
               "σ_m,T of the oxide–substrate pairs", ""},
              {t + ".d0", "number", "> 0", "m", "1.5e-9", "Si lattice spacing and mode of the SiO2 diameters", "--d0"},
              largest_key(t, "largest SiO2 diameter"),
              box_key(t, "[150e-9, 150e-9, 75e-9]", "cell [x, y, z]; x, y rounded to whole HCP cells"),
              {t + ".layer_thickness", "number", "≥ d0/2", "m", "5e-9", "SiO2 layer on the Si", ""},
              {t + ".body_diameter", "number", "≥ 3 d0", "m", "50e-9", "loose SiO2 cylinder (axis along y)", "--D"},
              clearance_key(t, "gaps layer–cylinder–plate, in d0"),
              {t + ".plate_thickness", "number", "[1, 10]", "1", "1.5", "rigid plate, in d0", ""},
              wall_thickness_key(t, "fixed Si wall at the bottom, in d0"),
              sliding_velocity_key(t, "sliding velocity of the plate"),
              pressure_key(t, "1e8", "normal pressure on the plate"),
              sliding_distance_key(t, "box x"),
              {t + ".settle_distance", "number", "> 0", "m", "2 d0",
               "loading at rest (damped) before sliding, for the time the plate takes to slide this far", ""},
              {t + ".settle_damping", "number", "[0, 1]", "1", "0.1", "global damping while settling, in c_c (6.64)", ""},
              {t + ".track_distance", "number", "≥ d0", "m", "2 d0", "slide between updates of the rolling body", ""},
              time_step_key(t),
              record_every_key(t),
              seed_key(t, "seed of the amorphous SiO2"),
              relax_tolerance_key(t),
              max_relax_steps_key(t),
              dump_every_key(t, 5000)});
    return s;
  }
  void run(const Config& inputs, RunContext& context) override {
    const EngineRanks ranks(engine_);
    finish(run_oxide_asperity_study(inputs, context), context, "oxide_asperity");
  }
};

}  // namespace
}  // namespace wearscale::studies

WEARSCALE_STUDY(OxideAsperityStudy)
