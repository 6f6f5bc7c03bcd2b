// The oxidized asperity of §9.3.3, Fig. 9.26 (`wearscale dem oxide-asperity`,
// [dem.oxide_asperity]): a loose SiO2 cylinder on an amorphous SiO2 layer over
// crystalline Si (HCP), rolled by a rigid plate pressed and slid over it. The
// cylinder picks up particles as it rolls and digs a trench towards the Si.
#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <memory>
#include <optional>
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

// What [dem.oxide_asperity] fills: the study's spec, the substrate and the
// SiO2–Si pairs as named and overridden, and the snapshots.
struct OxideAsperityKeys {
  OxideAsperitySpec spec;
  std::string substrate = "Si";
  std::optional<double> substrate_poisson, substrate_restitution;
  std::optional<double> interface_surface_energy, interface_tensile_strength, interface_shear_strength;
  long dump_every = 5000;
};

const KeyTable<OxideAsperityKeys>& oxide_asperity_keys() {
  using K = OxideAsperityKeys;
  using S = OxideAsperitySpec;
  const auto at = [](auto member) { return [member](K& k) -> auto& { return k.spec.*member; }; };
  const auto d0 = [](const K& k) { return k.spec.d0; };
  static const auto table = [&] {
    KeyTable<K> t;
    t.string("substrate", &K::substrate, "the HCP substrate's material (library or [materials.define] name)")
        .optional_number("substrate_poisson", &K::substrate_poisson, Range::open_closed(-1.0, 0.25),
                         units::dimensionless, "the substrate's modelled ν (Si's 0.27 exceeds the pair force's 1/4 (6.52))")
        .fallback("min(ν, 0.2)")
        .optional_number("substrate_restitution", &K::substrate_restitution, Range::open_closed(0.0, 1.0),
                         units::dimensionless, "the substrate's η")
        .fallback("record or 0.9")
        .optional_number("interface_surface_energy", &K::interface_surface_energy, Range::positive(),
                         units::surface_energy, "adhesion energy γ of the oxide–substrate pairs (the Si/SiO2 interface)")
        .unit("J/m^2")
        .fallback("√(γ_oxide γ_substrate)")
        .optional_number("interface_tensile_strength", &K::interface_tensile_strength, Range::positive(),
                         units::pressure, "σ_m,N of the oxide–substrate pairs")
        .fallback("the weaker σ_m,N")
        .optional_number("interface_shear_strength", &K::interface_shear_strength, Range::positive(), units::pressure,
                         "σ_m,T of the oxide–substrate pairs")
        .fallback("the weaker σ_m,T");
    add_d0(t, at(&S::d0), "Si lattice spacing and mode of the SiO2 diameters", false);
    add_largest(t, at(&S::largest), d0, "largest SiO2 diameter");
    add_box(t, at(&S::box), S{}.box, "cell [x, y, z]; x, y rounded to whole HCP cells");
    t.number("layer_thickness", at(&S::layer_thickness), Range::positive(), units::length, "SiO2 layer on the Si")
        .range_from([](const K& k) { return Range::at_least(0.5 * k.spec.d0); }, "≥ d0/2")
        .number("body_diameter", at(&S::body_diameter), Range::positive(), units::length,
                "loose SiO2 cylinder (axis along y)")
        .range_from([](const K& k) { return Range::at_least(3.0 * k.spec.d0); }, "≥ 3 d0")
        .flag("--D");
    add_clearance(t, at(&S::clearance), "gaps layer–cylinder–plate, in d0");
    t.number("plate_thickness", at(&S::plate_thickness), Range::closed(1.0, 10.0), "rigid plate, in d0");
    add_wall_thickness(t, at(&S::wall_thickness), "fixed Si wall at the bottom, in d0");
    add_sliding_velocity(t, at(&S::velocity), "sliding velocity of the plate");
    add_pressure(t, at(&S::pressure), [](const K& k) -> const CohesiveMaterial& { return k.spec.oxide; },
                 "normal pressure on the plate");
    add_time_step(t, at(&S::time_step));
    add_sliding_distance(t, at(&S::sliding_distance), [](const K& k) { return k.spec.box.x; }, "box x");
    t.number("settle_distance", at(&S::settle_distance), Range::positive(), units::length,
             "loading at rest (damped) before sliding, for the time the plate takes to slide this far")
        .computed_default([](const K& k) { return 2.0 * k.spec.d0; }, "2 d0")
        .number("settle_damping", at(&S::settle_damping), Range::closed(0.0, 1.0),
                "global damping while settling, in c_c (6.64)")
        .number("track_distance", at(&S::track_distance), Range::positive(), units::length,
                "slide between updates of the rolling body")
        .range_from([](const K& k) { return Range::at_least(k.spec.d0); }, "≥ d0")
        .computed_default([](const K& k) { return 2.0 * k.spec.d0; }, "2 d0");
    add_record_every(t, at(&S::record_every));
    add_seed(t, at(&S::seed), "seed of the amorphous SiO2");
    add_relaxation(t, at(&S::relax_tolerance), at(&S::max_relax_steps));
    add_dump_every(t, &K::dump_every);
    return t;
  }();
  return table;
}

// The substrate of the oxide-asperity study: a material of the library (or
// [materials.define]) by name, its ν at most the pair force's (6.52) and its η
// from the record or the key.
CohesiveMaterial substrate_material(const Config& root, const Config& c, const OxideAsperityKeys& k,
                                    double scaling_exponent) {
  materials::MaterialLibrary library;
  define_materials_from(library, root);
  if (!library.contains(k.substrate)) {
    std::string known;
    for (const auto& n : library.names()) known += (known.empty() ? "" : ", ") + n;
    throw c.error("substrate", fmt::format("unknown material '{}'", k.substrate), known);
  }
  const auto& record = library.get(k.substrate);
  const double eta = k.substrate_restitution.value_or(record.restitution ? *record.restitution : 0.9);
  CohesiveMaterial m = cohesive_material(record, scaling_exponent, eta);
  m.poisson = k.substrate_poisson.value_or(std::min(m.poisson, 0.2));
  require_modelled(m);
  return m;
}

// The SiO2–Si pairs: mix() of the two, with its adhesion energy and
// strengths replaced by the keys given.
CohesiveMaterial interface_material(const OxideAsperityKeys& k, const CohesiveMaterial& oxide,
                                    const CohesiveMaterial& substrate) {
  CohesiveMaterial m = mix(oxide, substrate);
  m.surface_energy = k.interface_surface_energy.value_or(m.surface_energy);
  m.tensile_strength = k.interface_tensile_strength.value_or(m.tensile_strength);
  m.shear_strength = k.interface_shear_strength.value_or(m.shear_strength);
  return m;
}

nlohmann::json run_oxide_asperity_study(const Config& root, const DemInputs& dem, RunContext& context) {
  const std::filesystem::path& out = context.output_dir();
  OxideAsperityKeys keys;
  keys.spec.oxide = dem.material;
  keys.spec.engine = dem.keys.engine;
  // The substrate's material is read from [materials] too before every key is checked.
  const Config c = read_study_keys(root, "dem.oxide_asperity", oxide_asperity_keys(), keys, false);
  OxideAsperitySpec& spec = keys.spec;
  spec.substrate = substrate_material(root, c, keys, spec.oxide.scaling_exponent);
  spec.interface = interface_material(keys, spec.oxide, spec.substrate);
  const long dump_every = keys.dump_every;
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
  const KeyTable<DemKeys>& dem_keys() const override {
    static const auto table =
        dem_table({.materials = "the oxide (layer, cylinder, plate): SiO2 or a [materials.define] name",
                   .default_material = oxide_default,
                   .cohesive_study = "oxide-asperity study"});
    return table;
  }
  Schema study_keys() const override { return oxide_asperity_keys().schema("dem.oxide_asperity"); }
  void run(const Config& inputs, RunContext& context) override {
    const EngineRanks ranks(engine_);
    finish(run_oxide_asperity_study(inputs, read_dem(inputs), context), context, "oxide_asperity");
  }
};

}  // namespace
}  // namespace wearscale::studies

WEARSCALE_STUDY(OxideAsperityStudy)
