// The DEM studies (`wearscale dem ...`), configured by the [dem] table of a
// case: the patch tests of §6.2, the sheared junction of §6.3, the sheared
// rough surfaces of §7.2 and the loose particles trapped between flat
// surfaces of §7.3. Each validates every key before it starts and writes its
// outputs into the run's folder. Each saves its state into the run's
// checkpoints as it goes (owner "dem/<study>", with the position of its
// snapshot file) and continues from the state restored: a killed run resumed
// gives the same outputs bit for bit (one thread).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <ctime>
#include <string_view>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/progress.hpp"
#include "wearscale/coupling/plots.hpp"
#include "wearscale/dem/contact_law.hpp"
#include "wearscale/dem/dump_writer.hpp"
#include "wearscale/dem/engine.hpp"
#ifdef WEARSCALE_DEM_LAMMPS
#include "wearscale/dem/lammps_engine.hpp"
#endif
#include "wearscale/dem/oxide_asperity.hpp"
#include "wearscale/dem/patch_test.hpp"
#include "wearscale/dem/rough_shear.hpp"
#include "wearscale/dem/sheared_junction.hpp"
#include "wearscale/dem/simulation.hpp"
#include "wearscale/dem/trapped_particles.hpp"
#include "wearscale/io/csv.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/io/material_definitions.hpp"
#include "wearscale/materials/material.hpp"
#include "wearscale/studies/study.hpp"

namespace wearscale::studies {

namespace {

using namespace dem;

CohesiveMaterial dem_material(const Config& root, const std::string& default_name = "table-6.4");

// [dem] law: the contact law between the particles, a registered name
// (contact_law.hpp); [dem] friction: its Coulomb μ, read for the hooke law.
void read_contact_law(const Config& root, std::string& law, double& friction) {
  const Config c = root.section("dem");
  law = c.string_or("law", "cohesive");
  const auto known = contact_law_names();
  if (std::find(known.begin(), known.end(), law) == known.end())
    throw c.error("law", fmt::format("unknown DEM contact law '{}'", law), fmt::format("{}", fmt::join(known, ", ")));
  if (law == "hooke") friction = c.number_or("friction", 0.5, Range::non_negative());
}

// [dem] engine: which engine integrates the study (engine.hpp): wearscale's
// own, or LAMMPS (solvers/dem/lammps, in a build with liblammps-dev).
std::string read_engine(const Config& root) {
  const Config c = root.section("dem");
  const std::string engine = c.choice_or("engine", "wearscale", {"wearscale", "lammps"});
#ifdef WEARSCALE_DEM_LAMMPS
  if (engine == "lammps") register_lammps_engine();
#else
  if (engine == "lammps")
    throw c.error("engine", "this build has no LAMMPS engine (it is built when CMake finds Debian's liblammps-dev, "
                  "option WEARSCALE_DEM_LAMMPS)", "wearscale");
#endif
  return engine;
}

// While one lives on rank 0 of an mpirun job, the LAMMPS engines the study
// makes span every rank (the others serve them: DemStudy::run_other_rank).
class EngineRanks {
 public:
  explicit EngineRanks([[maybe_unused]] const std::string& engine) {
#ifdef WEARSCALE_DEM_LAMMPS
    if (engine == "lammps") served_.emplace();
#endif
  }

 private:
#ifdef WEARSCALE_DEM_LAMMPS
  std::optional<LammpsServedRun> served_;
#endif
};

// The studies that measure the cohesive law itself refuse another one.
void require_cohesive_law(const Config& root, const char* study) {
  std::string law;
  double friction = 0.0;
  read_contact_law(root, law, friction);
  if (law != "cohesive")
    throw root.section("dem").error("law", fmt::format("the {} measures the cohesive law's strengths", study), "cohesive");
}

// The keys both wear studies share (the sliding cell), read from `c`; the
// cell size is read by each study. Every value is range-checked here.
void read_sliding_cell(const Config& root, const Config& c, SlidingCellSpec& cell) {
  cell.material = dem_material(root);
  read_contact_law(root, cell.law, cell.friction);
  // [dem] history: "touching" carries tangential histories over neighbour
  // rebuilds for touching pairs only, as LAMMPS did in the thesis' runs.
  cell.history_of_touching_pairs_only =
      root.section("dem").choice_or("history", "kept", {"kept", "touching"}) == "touching";
  cell.engine = read_engine(root);
  cell.d0 = c.number("d0", Range::positive(), units::length);
  cell.largest = c.number_or("largest", 1.25 * cell.d0, Range::at_least(cell.d0), units::length);
  cell.velocity = c.number_or("velocity", 10.0, Range::open(0.0, 1000.0), units::velocity);
  cell.pressure = c.number_or("pressure", 0.5e9, Range::closed(0.0, cell.material.tensile_strength), units::pressure);
  cell.time_step = c.number_or("time_step", 0.1, Range::open(0.0, 1.0));
  cell.settle_distance = c.number_or("settle_distance", cell.d0, Range::non_negative(), units::length);
  cell.wall_damping = c.number_or("wall_damping", 0.0, Range::closed(0.0, 1.0));
  cell.wall_thickness = c.number_or("wall_thickness", 1.5, Range::closed(1.0, 10.0));
  cell.record_every = c.integer_or("record_every", 200, Range::at_least(1));
  cell.seed = static_cast<std::uint64_t>(c.integer_or("seed", 1, Range::closed(0, 4294967295.0)));
  cell.relax_tolerance = c.number_or("relax_tolerance", 1e-4, Range::open(0.0, 1e-2));
  cell.max_relax_steps = c.integer_or("max_relax_steps", 20000, Range::at_least(0));
}

// The cell size L × W × H: W at least the largest particle, L at least
// `min_length`, H at least `min_height`.
Vec3 read_cell_box(const Config& c, const SlidingCellSpec& cell, double default_length, double min_length,
                   double default_height, double min_height) {
  const double d_l = cell.largest;
  Vec3 box;
  box.x = c.number_or("length", default_length, Range::at_least(min_length), units::length);
  // Periodic down to the largest particle (a pair meets several images of a
  // neighbour across a thinner-than-cutoff depth, neighbor_list.hpp).
  box.y = c.number_or("depth", 3.5 * cell.d0, Range::at_least(d_l), units::length);
  box.z = c.number_or("height", default_height, Range::at_least(min_height), units::length);
  return box;
}

// The history of a wear study as CSV (sliding distance and forces in the
// columns plot_junction_force reads) and as an HDF5 table; returns the
// open HDF5 file for the results.
std::vector<std::string> write_sliding_history(const std::vector<SlidingSample>& history, const std::filesystem::path& csv,
                                               H5Writer& h5, const std::string& title) {
  std::vector<double> t, s, ft, fn, ke, worn, sa_b, sa_t;
  for (const auto& h : history) {
    t.push_back(h.time);
    s.push_back(h.sliding);
    ft.push_back(h.tangential_force);
    fn.push_back(h.normal_force);
    ke.push_back(h.kinetic_energy);
    worn.push_back(h.worn);
    sa_b.push_back(h.roughness_bottom);
    sa_t.push_back(h.roughness_top);
  }
  const std::vector<std::string> names = {"time",           "sliding", "tangential_force", "normal_force",
                                          "kinetic_energy", "worn",    "roughness_bottom", "roughness_top"},
                                 units = {"s", "m", "N", "N", "J", "1", "m", "m"};
  write_csv(csv, names, {t, s, ft, fn, ke, worn, sa_b, sa_t}, units, {title});
  h5.write_table("/history", names, {t, s, ft, fn, ke, worn, sa_b, sa_t}, units);
  return {csv.string(), h5.final_path().string()};
}

// Snapshots for OVITO every `every` steps (and the first and last), with
// the worn flag as an extra column.
// A study's hooks into the run's checkpoints (owner "dem/<study>"). With a
// snapshot file, each checkpoint also records how far that file has got, and
// a resumed study continues it.
RunCheckpoints study_checkpoints(Checkpointer* checkpoints, const std::string& owner, DumpWriter* dump) {
  RunCheckpoints hooks;
  if (checkpoints == nullptr) return hooks;
  hooks.from = checkpoints->restored(owner);
  if (hooks.from != nullptr) {
    log::info("{}: resumes at step {} from {}", owner, hooks.from->step, checkpoints->file().string());
    if (dump != nullptr && hooks.from->has("dump.position")) {
      const auto& at = tallies(*hooks.from, "dump.position", 2);
      if (!dump->resume({hooks.from->text("dump.partial"), static_cast<std::uintmax_t>(at[0]),
                         static_cast<std::size_t>(at[1])}))
        log::warn("{}: the snapshots written before step {} are gone ({}); {} holds those from step {} on", owner,
                  hooks.from->step, hooks.from->text("dump.partial"), dump->final_path().string(), hooks.from->step);
    }
  }
  hooks.at_sample = [checkpoints, owner, dump](long step, const std::function<CheckpointState()>& make) {
    checkpoints->at_step(owner, step, [&] {
      CheckpointState st = make();
      if (dump != nullptr) {
        const auto at = dump->position();
        st.put_text("dump.partial", at.partial);
        st.put("dump.position", std::vector<double>{static_cast<double>(at.bytes), static_cast<double>(at.frames)});
      }
      return st;
    });
  };
  return hooks;
}

// A progress bar that starts at the resumed step.
std::unique_ptr<Progress> progress_bar(const std::string& name, long planned, const RunCheckpoints& hooks) {
  auto bar = std::make_unique<Progress>(name, static_cast<double>(planned));
  if (hooks.from != nullptr) bar->start_at(static_cast<double>(hooks.from->step));
  return bar;
}

struct SlidingDumps {
  DumpWriter writer;
  long every;
  std::unique_ptr<Progress> bar;
  void operator()(const SlidingCell& cell, long step, long planned, const std::string& name, const RunCheckpoints& hooks) {
    if (!bar) bar = progress_bar(name, planned, hooks);
    if (writer.frames() == 0) write(cell);
    bar->update(static_cast<double>(step));
    if (every > 0 && (step % every < cell_record_every || step == planned)) write(cell);
  }
  void write(const SlidingCell& cell) {
    const auto worn = cell.worn_flags();
    writer.write(cell.engine(), {{"worn", worn}});
  }
  long cell_record_every = 1;
};

CohesiveMaterial dem_material(const Config& root, const std::string& default_name) {
  const Config c = root.section("dem");
  const std::string name = c.string_or("material", default_name);
  const double s = c.number_or("scaling_exponent", 0.5, Range::closed(0.0, 1.0));
  CohesiveMaterial m;
  if (name == "table-6.4") {
    m = patch_test_targets();
    m.scaling_exponent = s;
  } else {
    materials::MaterialLibrary library;
    define_materials_from(library, root);
    if (!library.contains(name)) {
      std::string known = "table-6.4";
      for (const auto& n : library.names()) known += ", " + n;
      throw c.error("material", fmt::format("unknown material '{}'", name), known);
    }
    std::optional<double> eta;
    if (c.has("restitution")) eta = c.number("restitution", Range{0.0, 1.0, true, false});
    try {
      m = cohesive_material(library.get(name), s, eta);
    } catch (const InputError& e) {
      throw c.error("restitution", e.what(), "0 < η ≤ 1");
    }
  }
  if (c.has("restitution")) m.restitution = c.number("restitution", Range{0.0, 1.0, true, false});
  // Read over all ν > −1 so that ν in (1/4, 1/2] meets the reason below, not "(-1, 0.5)".
  if (c.has("poisson")) m.poisson = c.number("poisson", Range::greater_than(-1.0));
  if (!(m.poisson <= 0.25))
    throw c.error("poisson",
                  fmt::format("ν = {} cannot be modelled by the DEM pair force: central pair forces give ν ≤ 1/4 "
                              "(the tangential cross section A_T of (6.52) would be negative)",
                              m.poisson),
                  "-1 < ν ≤ 0.25");
  require_modelled(m);
  return m;
}

nlohmann::json run_patch_test_study(const Config& root, RunContext& context) {
  const std::filesystem::path& out = context.output_dir();
  Checkpointer* checkpoints = &context.checkpoints();
  PatchTestSpec spec;
  spec.material = dem_material(root);
  require_cohesive_law(root, "patch test");
  spec.engine = read_engine(root);
  const Config c = root.section("dem.patch_test");
  const bool unitless = spec.material.name == "table-6.4";
  spec.amorphous = c.choice_or("lattice", "hcp", {"hcp", "amorphous"}) == "amorphous";
  const double d_c = critical_diameter(spec.material);
  spec.d0 = c.has("d0") ? c.number("d0", Range::positive(), unitless ? units::dimensionless : units::length) : 0.6 * d_c;
  spec.load_along_c_axis = c.boolean_or("load_along_c_axis", false);
  spec.length = c.number_or("length", 25.0, Range::closed(PatchTestSpec::min_length, PatchTestSpec::max_length));
  // At least the largest particle (1.25 d0, amorphous); an HCP sample takes
  // whole cells of √(8/3) d0: 1.6 is one cell, the 2.4 nm depth of §7.1.1.
  spec.width = c.number_or("width", 3.0, Range::closed(PatchTestSpec::min_width, PatchTestSpec::max_width));
  spec.load = c.number_or("load", 0.01, Range::open(0.0, spec.material.tensile_strength / spec.material.young));
  spec.time_step = c.number_or("time_step", 0.1, Range::open(0.0, 1.0));
  spec.strain_rate = c.number_or("strain_rate", 1e-5, Range::open(0.0, PatchTestSpec::max_strain_rate));
  spec.strengths = c.boolean_or("strengths", true);
  spec.max_elastic_steps = c.integer_or("max_elastic_steps", 40000,
                                        Range::at_least(static_cast<double>(PatchTestSpec::min_elastic_steps)));
  spec.seed = static_cast<unsigned>(c.integer_or("seed", 1, Range::closed(0, 4294967295.0)));
  root.reject_unknown_keys();

  log::info("DEM patch test: {} {}, d0 = {:g} (d_min = {:g}, d_c = {:g}), ν target {:g}", spec.amorphous ? "amorphous" : "HCP",
            spec.material.name, spec.d0, minimum_diameter(spec.material), d_c, spec.material.poisson);
  std::unique_ptr<Progress> bar;
  std::string phase;
  const auto hooks = study_checkpoints(checkpoints, "dem/patch_test", nullptr);
  const auto result = run_patch_test(
      spec,
      [&](const std::string& name, long done, long planned) {
        if (name != phase) {
          bar = std::make_unique<Progress>("patch test: " + name, static_cast<double>(planned));
          phase = name;
        }
        bar->update(static_cast<double>(done));
      },
      hooks);
  bar.reset();

  const std::string stress_unit = unitless ? "1" : "Pa";
  context.report("young", result.young, stress_unit, fmt::format("measured E (target {:g})", spec.material.young));
  context.report("poisson", result.poisson, "1", fmt::format("measured ν (target {:g})", spec.material.poisson));
  context.report("d_min", result.d_min, unitless ? "1" : "m", "minimum particle size 4γ/σ_m,N (6.62)");
  context.report("d_c", result.d_c, unitless ? "1" : "m", "critical particle size 4γE/σ_m,N² (6.35)");
  context.report("particles", static_cast<double>(result.particles), "1", "particles in the sample");
  context.report("elastic_steps", static_cast<double>(result.elastic_steps), "1",
         result.elastic_converged ? "steps to rest under the load" : "steps run (the wall had not stopped)");
  std::vector<std::string> names{"E", "nu"};
  std::vector<double> measured{result.young, result.poisson}, target{spec.material.young, spec.material.poisson};
  if (result.tensile_strength) {
    context.report("tensile_strength", *result.tensile_strength, stress_unit,
           fmt::format("peak σ_yy in tension (target {:g}, (6.63))", result.target_tensile));
    context.report("shear_strength", *result.shear_strength, stress_unit,
           fmt::format("peak σ_xy in shear (target {:g})", result.target_shear));
    names.insert(names.end(), {"sigma_mN", "sigma_mT"});
    measured.insert(measured.end(), {*result.tensile_strength, *result.shear_strength});
    target.insert(target.end(), {result.target_tensile, result.target_shear});
  }
  // One row: each quantity measured and its target, in its own unit.
  std::vector<std::string> columns, units;
  std::vector<std::vector<double>> values;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string unit = names[k] == "nu" ? "1" : stress_unit;
    columns.insert(columns.end(), {names[k], names[k] + "_target"});
    units.insert(units.end(), {unit, unit});
    values.push_back({measured[k]});
    values.push_back({target[k]});
  }
  const std::vector<std::span<const double>> spans(values.begin(), values.end());
  const auto csv = out / "patch_test.csv";
  write_csv(csv, columns, spans, units,
            {fmt::format("DEM patch test (§6.2), {} {}, d0 = {:g}", spec.amorphous ? "amorphous" : "HCP", spec.material.name, spec.d0),
             "each quantity measured and its target (<name>_target)"});
  return {{"files", {csv.string()}}};
}

nlohmann::json run_junction_study(const Config& root, RunContext& context) {
  const std::filesystem::path& out = context.output_dir();
  Checkpointer* checkpoints = &context.checkpoints();
  ShearedJunctionSpec spec;
  spec.material = dem_material(root);
  require_cohesive_law(root, "junction study");
  spec.engine = read_engine(root);
  const Config c = root.section("dem.junction");
  spec.diameter = c.number("diameter", Range::positive(), units::length);
  spec.d0 = c.number("d0", Range::positive(), units::length);
  spec.largest = c.number_or("largest", 1.25 * spec.d0, Range::at_least(spec.d0), units::length);
  if (c.has("box")) {
    const auto b = c.numbers("box", Range::positive(), units::length);
    if (b.size() != 3) throw c.error("box", fmt::format("{} values", b.size()), "three lengths [x, y, z]");
    spec.box = {b[0], b[1], b[2]};
  }
  spec.velocity = c.number_or("velocity", 10.0, Range::positive(), units::velocity);
  // As the sliding cell's: beyond the material's normal strength σ_m,N the cohesive model no longer holds a
  // solid (a pressure of 1e15 Pa crushed the sample and reported no resistance to sliding).
  spec.pressure =
      c.number_or("pressure", 100e6, Range::closed(0.0, spec.material.tensile_strength), units::pressure);
  spec.time_step = c.number_or("time_step", 0.1, Range::open(0.0, 1.0));
  spec.sliding_distance = c.number_or("sliding_distance", 1.5 * spec.diameter, Range::positive(), units::length);
  spec.seed = static_cast<unsigned>(c.integer_or("seed", 1, Range::closed(0, 4294967295.0)));
  const long dump_every = c.integer_or("dump_every", 2000, Range::at_least(0));
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

nlohmann::json run_rough_shear_study(const Config& root, RunContext& context) {
  const std::filesystem::path& out = context.output_dir();
  Checkpointer* checkpoints = &context.checkpoints();
  RoughShearSpec spec;
  const Config c = root.section("dem.rough_shear");
  read_sliding_cell(root, c, spec.cell);
  const double d0 = spec.cell.d0;
  spec.cell.box = read_cell_box(c, spec.cell, 25.0 * d0, 10.0 * d0, 14.0 * d0, 2.0 * (spec.cell.wall_thickness + 2.0) * d0);
  spec.roughness = c.number_or("roughness", 0.02, Range::closed(0.0, 0.1));
  spec.hurst = c.number_or("hurst", 0.8, Range::open_closed(0.0, 1.0));
  spec.shortest_wavelength = c.number_or("shortest_wavelength", 4.0, Range::at_least(2.0));
  spec.cell.sliding_distance = c.number_or("sliding_distance", spec.cell.box.x, Range::positive(), units::length);
  const long dump_every = c.integer_or("dump_every", 2000, Range::at_least(0));
  root.reject_unknown_keys();

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

nlohmann::json run_trapped_particles_study(const Config& root, RunContext& context) {
  const std::filesystem::path& out = context.output_dir();
  Checkpointer* checkpoints = &context.checkpoints();
  TrappedParticlesSpec spec;
  const Config c = root.section("dem.trapped_particles");
  read_sliding_cell(root, c, spec.cell);
  const double d0 = spec.cell.d0;
  spec.count = static_cast<int>(c.integer_or("count", 3, Range::closed(1, 16)));
  spec.diameter = c.number("diameter", Range::at_least(3.0 * d0), units::length);
  spec.clearance = c.number_or("clearance", 0.25, Range::closed_open(0.0, 1.0));
  spec.fit_from = c.number_or("fit_from", 0.0, Range::closed_open(0.0, 1.0));
  const double min_height = spec.diameter + 2.0 * (spec.cell.wall_thickness + 2.0) * d0;
  const double min_length = spec.count * (spec.diameter + d0);
  spec.cell.box = read_cell_box(c, spec.cell, 3.0 * spec.count * spec.diameter, min_length, min_height + 2.0 * d0,
                                min_height);
  spec.cell.sliding_distance = c.number_or("sliding_distance", spec.cell.box.x, Range::positive(), units::length);
  const long dump_every = c.integer_or("dump_every", 2000, Range::at_least(0));
  root.reject_unknown_keys();

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
  spec.oxide = dem_material(root, "SiO2");
  spec.engine = read_engine(root);
  const Config c = root.section("dem.oxide_asperity");
  spec.substrate = substrate_material(root, c, spec.oxide.scaling_exponent);
  spec.interface = interface_material(c, spec.oxide, spec.substrate);
  spec.d0 = c.number_or("d0", 1.5e-9, Range::positive(), units::length);
  spec.largest = c.number_or("largest", 1.25 * spec.d0, Range::at_least(spec.d0), units::length);
  if (c.has("box")) {
    const auto b = c.numbers("box", Range::positive(), units::length);
    if (b.size() != 3) throw c.error("box", fmt::format("{} values", b.size()), "three lengths [x, y, z]");
    spec.box = {b[0], b[1], b[2]};
  }
  spec.layer_thickness = c.number_or("layer_thickness", 5e-9, Range::at_least(0.5 * spec.d0), units::length);
  spec.body_diameter = c.number_or("body_diameter", 50e-9, Range::at_least(3.0 * spec.d0), units::length);
  spec.clearance = c.number_or("clearance", 0.25, Range::closed_open(0.0, 1.0));
  spec.plate_thickness = c.number_or("plate_thickness", 1.5, Range::closed(1.0, 10.0));
  spec.wall_thickness = c.number_or("wall_thickness", 1.5, Range::closed(1.0, 10.0));
  spec.velocity = c.number_or("velocity", 10.0, Range::open(0.0, 1000.0), units::velocity);
  spec.pressure = c.number_or("pressure", 100e6, Range::closed(0.0, spec.oxide.tensile_strength), units::pressure);
  spec.time_step = c.number_or("time_step", 0.1, Range::open(0.0, 1.0));
  spec.sliding_distance = c.number_or("sliding_distance", spec.box.x, Range::positive(), units::length);
  spec.settle_distance = c.number_or("settle_distance", 2.0 * spec.d0, Range::positive(), units::length);
  spec.settle_damping = c.number_or("settle_damping", 0.1, Range::closed(0.0, 1.0));
  spec.track_distance = c.number_or("track_distance", 2.0 * spec.d0, Range::at_least(spec.d0), units::length);
  spec.record_every = c.integer_or("record_every", 200, Range::at_least(1));
  spec.seed = static_cast<std::uint64_t>(c.integer_or("seed", 1, Range::closed(0, 4294967295.0)));
  spec.relax_tolerance = c.number_or("relax_tolerance", 1e-4, Range::open(0.0, 1e-2));
  spec.max_relax_steps = c.integer_or("max_relax_steps", 20000, Range::at_least(0));
  const long dump_every = c.integer_or("dump_every", 5000, Range::at_least(0));
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

// A measured E ≤ 0 or ν outside (−1, 0.5) is no elastic solid: the patch
// test failed to measure one (exit 1), whatever the sample did.
void require_elastic_bounds(const nlohmann::json& results) {
  const double e = results["young"]["value"].get<double>(), nu = results["poisson"]["value"].get<double>();
  if (!(e > 0.0) || !(nu > -1.0 && nu < 0.5))
    throw NumericalError("DEM patch test", 0, "elastic constants",
                         fmt::format("measured E = {:g}, ν = {:g}: not an elastic solid (allowed: E > 0, −1 < ν < 0.5); "
                                     "the sample did not respond elastically to the load (compare d0 with the printed "
                                     "d_min and the time step)",
                                     e, nu));
}

// What the four DEM studies share: case name "dem", folder out/dem-<study>,
// [dem] material keys, and the outputs their driver lists.
class DemStudy : public Study {
 public:
  std::string default_case_name() const override { return "dem"; }
  // [dem] engine = "lammps": under mpirun one run over every rank (LAMMPS'
  // domain decomposition), rank 0 writing the outputs and checkpoints.
  std::vector<std::string> prepare(Config& inputs) override {
    engine_ = read_engine(inputs);
    return {};
  }
  bool distributed() const override { return engine_ == "lammps"; }
  bool resumes_distributed() const override { return engine_ == "lammps"; }
  bool calls_mpi() const override { return engine_ == "lammps"; }
  void run_other_rank(const Config&) override {
#ifdef WEARSCALE_DEM_LAMMPS
    serve_lammps_engines();
#endif
  }
  std::string default_output_dir() const override {
    std::string leaf = name().substr(name().find('/') + 1);
    std::replace(leaf.begin(), leaf.end(), '_', '-');
    return "out/dem-" + leaf;
  }

 protected:
  std::string engine_ = "wearscale";
  // The driver's outputs (files, verdict) into the context; a sheared study's force history plotted.
  static void finish(const nlohmann::json& outputs, RunContext& context, const std::string& history) {
    for (const auto& f : outputs["files"]) context.add_file(f.get<std::string>());
    if (!outputs.contains("verdict")) return;
    const std::string verdict = outputs["verdict"].get<std::string>();
    context.note("verdict", verdict);
    const auto& out = context.output_dir();
    // The title states the parameters, then the verdict.
    const std::string title =
        outputs.contains("caption") ? outputs["caption"].get<std::string>() + ": " + verdict : verdict;
    context.add_figure(coupling::junction_force_figure(history + "_force", title, out / (history + "_history.csv"), out));
  }
  // [dem]: the material (dem_material) and the contact law (read_contact_law).
  static Schema material_keys(const std::string& flag_doc) {
    return {{"dem.material", "string", "", "", "table-6.4", flag_doc, "--material"},
            {"dem.poisson", "number", "(-1, 0.25]", "1", "the material's", "target Poisson's ratio", ""},
            {"dem.restitution", "number", "(0, 1]", "1", "the material's", "coefficient of restitution", ""},
            {"dem.scaling_exponent", "number", "[0, 1]", "1", "0.5", "size-scaling exponent s of (6.57)", ""},
            {"dem.law", "choice", fmt::format("{}", fmt::join(contact_law_names(), " | ")), "", "cohesive",
             "contact law between the particles (contact_law.hpp)", ""},
            {"dem.friction", "number", "≥ 0", "1", "0.5", "Coulomb μ of the hooke law", ""},
            {"dem.engine", "choice", std::string(engine_choices), "", "wearscale",
             "the engine that integrates the particles (LAMMPS: over every rank under mpirun)", ""}};
  }
  // The sliding cell of the wear studies (read_sliding_cell, and the dumps).
  static Schema sliding_keys(const std::string& table, const std::string& slide_default) {
    return {{"dem.history", "choice", "kept | touching", "", "kept",
             "tangential histories over neighbour rebuilds: kept for every pair in reach (6.4), or for touching pairs "
             "only (the thesis' LAMMPS runs)",
             ""},
            {table + ".d0", "number", "> 0", "m", "", "mode of the particle diameters", "--d0"},
            {table + ".velocity", "number", "(0, 1000)", "m/s", "10", "sliding velocity of the top wall", "--velocity"},
            {table + ".pressure", "number", "[0, σ_m,N]", "Pa", "5e8", "normal pressure on the top wall", "--pressure"},
            {table + ".sliding_distance", "number", "> 0", "m", slide_default, "sliding distance", "--slide"},
            {table + ".seed", "integer", "[0, 4294967295]", "1", "1", "seed of the amorphous sample", "--seed"},
            {table + ".largest", "number", "≥ d0", "m", "1.25 d0", "largest particle diameter", ""},
            {table + ".time_step", "number", "(0, 1)", "1", "0.1", "time step in Δt_c", ""},
            {table + ".settle_distance", "number", "≥ 0", "m", "d0", "loading at rest before sliding, for the time the wall takes to slide this far", ""},
            {table + ".wall_damping", "number", "[0, 1]", "1", "0", "damping of the pressed wall's normal motion, in the critical damping", ""},
            {table + ".wall_thickness", "number", "[1, 10]", "1", "1.5", "wall thickness in d0", ""},
            {table + ".record_every", "integer", "≥ 1", "1", "200", "steps per history sample", ""},
            {table + ".relax_tolerance", "number", "(0, 0.01)", "1", "1e-4", "stress tolerance of the relaxation, in E", ""},
            {table + ".max_relax_steps", "integer", "≥ 0", "1", "20000", "relaxation step limit", ""},
            {table + ".depth", "number", "≥ largest", "m", "3.5 d0", "cell depth W (periodic)", ""},
            {table + ".dump_every", "integer", "≥ 0", "1", "2000", "steps between OVITO dump frames (0: none)", ""}};
  }
};

class PatchTestStudy final : public DemStudy {
 public:
  std::string name() const override { return "dem/patch_test"; }
  std::string summary() const override {
    return "E, ν (confined compression) and σ_m,N, σ_m,T (walls pulled, sheared) of a DEM sample (§6.2)";
  }
  Schema schema() const override {
    Schema s = material_keys("table-6.4 (Table 6.4, unitless), Si, SiO2 or a [materials.define] name");
    s[1].flag = "--nu";
    s[3].flag = "--s";
    s.insert(s.end(),
             {{"dem.patch_test.lattice", "choice", "hcp | amorphous", "", "hcp", "sample lattice", "--lattice"},
              {"dem.patch_test.d0", "number", "> 0", "m", "0.6 d_c",
               "particle diameter (HCP) or mode of diameters, e.g. 90 or \"6 nm\"", "--d0"},
              {"dem.patch_test.length", "number", "[6, 400]", "1", "25", "sample length L in d0", "--length"},
              {"dem.patch_test.width", "number", "[1.25, 100]", "1", "3", "sample width in d0", ""},
              {"dem.patch_test.seed", "integer", "≥ 0", "1", "", "seed of the amorphous sample", "--seed"},
              {"dem.patch_test.strengths", "boolean", "", "", "true", "also pull and shear the walls", "--no-strengths",
               "false"},
              {"dem.patch_test.load_along_c_axis", "boolean", "", "", "false",
               "HCP: the c axis (stacking direction) along the load", ""},
              {"dem.patch_test.load", "number", "(0, σ_m,N/E)", "1", "0.01", "compressive stress of the elastic test, in E", ""},
              {"dem.patch_test.time_step", "number", "(0, 1)", "1", "0.1", "time step in Δt_c", ""},
              {"dem.patch_test.strain_rate", "number", "(0, 0.01)", "1", "1e-5", "strength tests: ε̇ Δt", ""},
              {"dem.patch_test.max_elastic_steps", "integer", "≥ 1000", "1", "40000",
               "step limit of the elastic compression", ""}});
    return s;
  }
  void run(const Config& inputs, RunContext& context) override {
    const EngineRanks ranks(engine_);
    const auto outputs = run_patch_test_study(inputs, context);
    require_elastic_bounds(context.results());
    finish(outputs, context, "");
  }
};
}  // namespace
}  // namespace wearscale::studies
WEARSCALE_STUDY(PatchTestStudy)

namespace wearscale::studies {
namespace {
class JunctionStudy final : public DemStudy {
 public:
  std::string name() const override { return "dem/junction"; }
  std::string summary() const override {
    return "a cylindrical junction sheared between two surfaces (§6.3): plastic deformation or a rolling wear particle";
  }
  Schema schema() const override {
    Schema s = material_keys("Si, SiO2 or a [materials.define] name");
    s.push_back({"dem.junction.diameter", "number", "> 0", "m", "", "junction diameter D, e.g. 20e-9 or \"20 nm\"", "--D"});
    // The junction reads its own keys (not the sliding cell's): these.
    const std::string t = "dem.junction.";
    s.insert(s.end(),
             {{t + "d0", "number", "> 0", "m", "", "mode of the particle diameters", "--d0"},
              {t + "velocity", "number", "> 0", "m/s", "10", "sliding velocity of the top wall", "--velocity"},
              {t + "pressure", "number", "≥ 0", "Pa", "1e8", "normal pressure on the top wall", "--pressure"},
              {t + "sliding_distance", "number", "> 0", "m", "1.5 D", "sliding distance", "--slide"},
              {t + "seed", "integer", "[0, 4294967295]", "1", "1", "seed of the amorphous sample", "--seed"},
              {t + "largest", "number", "≥ d0", "m", "1.25 d0", "largest particle diameter", ""},
              {t + "box", "list", "three lengths > 0", "m", "from D", "cell size [x, y, z]", ""},
              {t + "time_step", "number", "(0, 1)", "1", "0.1", "time step in Δt_c", ""},
              {t + "dump_every", "integer", "≥ 0", "1", "2000", "steps between OVITO dump frames (0: none)", ""}});
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

namespace wearscale::studies {
namespace {
class RoughShearStudy final : public DemStudy {
 public:
  std::string name() const override { return "dem/rough_shear"; }
  std::string summary() const override {
    return "two rough surfaces sheared under a normal pressure (§7.2): worn particles, F_T history, Sa evolution";
  }
  Schema schema() const override {
    Schema s = material_keys("Si, SiO2 or a [materials.define] name");
    s.push_back({"dem.rough_shear.length", "number", "> 0", "m", "", "cell length L (thesis: 25, 50, 100 d0)", "--length"});
    s.push_back({"dem.rough_shear.roughness", "number", "[0, 0.1]", "1", "0.02", "initial Sa / L (thesis: 0.01, 0.02, 0.04)",
                 "--roughness"});
    s.push_back({"dem.rough_shear.height", "number", "≥ 2 (wall_thickness + 2) d0", "m", "14 d0", "cell height H", ""});
    s.push_back({"dem.rough_shear.hurst", "number", "(0, 1]", "1", "0.8", "Hurst exponent of the initial surfaces", ""});
    s.push_back({"dem.rough_shear.shortest_wavelength", "number", "≥ 2", "1", "4",
                 "shortest wavelength of the initial surfaces in d0", ""});
    const Schema sliding = sliding_keys("dem.rough_shear", "L");
    s.insert(s.end(), sliding.begin(), sliding.end());
    return s;
  }
  void run(const Config& inputs, RunContext& context) override {
    const EngineRanks ranks(engine_);
    finish(run_rough_shear_study(inputs, context), context, "rough_shear");
  }
};
}  // namespace
}  // namespace wearscale::studies
WEARSCALE_STUDY(RoughShearStudy)

namespace wearscale::studies {
namespace {
class TrappedParticlesStudy final : public DemStudy {
 public:
  std::string name() const override { return "dem/trapped_particles"; }
  std::string summary() const override {
    return "n loose particles sheared between flat surfaces (§7.3): rolling particles or a shear band";
  }
  Schema schema() const override {
    Schema s = material_keys("Si, SiO2 or a [materials.define] name");
    s.push_back({"dem.trapped_particles.count", "integer", "1 … 16", "1", "3", "number of loose particles (thesis: 2 to 4)", "--n"});
    s.push_back({"dem.trapped_particles.diameter", "number", "> 0", "m", "", "diameter of the loose particles (= the gap)", "--D"});
    s.push_back({"dem.trapped_particles.length", "number", "> 0", "m", "3 n D", "cell length L", "--length"});
    s.push_back({"dem.trapped_particles.height", "number", "≥ D + 2 (wall_thickness + 2) d0", "m",
                 "D + 2 (wall_thickness + 3) d0", "cell height H", ""});
    s.push_back({"dem.trapped_particles.clearance", "number", "[0, 1)", "1", "0.25",
                 "clearance between the loose particles and the surfaces, in d0", ""});
    s.push_back({"dem.trapped_particles.fit_from", "number", "[0, 1)", "1", "0",
                 "the rigid-body fit of the loose particles runs from this fraction of the slide", ""});
    const Schema sliding = sliding_keys("dem.trapped_particles", "L");
    s.insert(s.end(), sliding.begin(), sliding.end());
    return s;
  }
  void run(const Config& inputs, RunContext& context) override {
    const EngineRanks ranks(engine_);
    finish(run_trapped_particles_study(inputs, context), context, "trapped_particles");
  }
};

}  // namespace
}  // namespace wearscale::studies
WEARSCALE_STUDY(TrappedParticlesStudy)

namespace wearscale::studies {
namespace {
class OxideAsperityStudy final : public DemStudy {
 public:
  std::string name() const override { return "dem/oxide_asperity"; }
  std::string summary() const override {
    return "a loose SiO2 cylinder rolled by a plate on an oxidized Si surface (§9.3.3, Fig. 9.26): growth, trench";
  }
  Schema schema() const override {
    Schema s = material_keys("the oxide (layer, cylinder, plate): SiO2 or a [materials.define] name");
    s[0].fallback = "SiO2";
    const std::string t = "dem.oxide_asperity.";
    s.insert(s.end(),
             {{t + "substrate", "string", "", "", "Si", "the HCP substrate's material (library or [materials.define] name)", ""},
              {t + "substrate_poisson", "number", "(-1, 0.25]", "1", "min(ν, 0.2)",
               "the substrate's modelled ν (Si's 0.27 exceeds the pair force's 1/4 (6.52))", ""},
              {t + "substrate_restitution", "number", "(0, 1]", "1", "record or 0.9", "the substrate's η", ""},
              {t + "interface_surface_energy", "number", "> 0", "J/m^2", "√(γ_oxide γ_substrate)",
               "adhesion energy γ of the oxide–substrate pairs (the Si/SiO2 interface)", ""},
              {t + "interface_tensile_strength", "number", "> 0", "Pa", "the weaker σ_m,N",
               "σ_m,N of the oxide–substrate pairs", ""},
              {t + "interface_shear_strength", "number", "> 0", "Pa", "the weaker σ_m,T",
               "σ_m,T of the oxide–substrate pairs", ""},
              {t + "d0", "number", "> 0", "m", "1.5e-9", "Si lattice spacing and mode of the SiO2 diameters", "--d0"},
              {t + "largest", "number", "≥ d0", "m", "1.25 d0", "largest SiO2 diameter", ""},
              {t + "box", "list", "three lengths > 0", "m", "[150e-9, 150e-9, 75e-9]",
               "cell [x, y, z]; x, y rounded to whole HCP cells", ""},
              {t + "layer_thickness", "number", "≥ d0/2", "m", "5e-9", "SiO2 layer on the Si", ""},
              {t + "body_diameter", "number", "≥ 3 d0", "m", "50e-9", "loose SiO2 cylinder (axis along y)", "--D"},
              {t + "clearance", "number", "[0, 1)", "1", "0.25", "gaps layer–cylinder–plate, in d0", ""},
              {t + "plate_thickness", "number", "[1, 10]", "1", "1.5", "rigid plate, in d0", ""},
              {t + "wall_thickness", "number", "[1, 10]", "1", "1.5", "fixed Si wall at the bottom, in d0", ""},
              {t + "velocity", "number", "(0, 1000)", "m/s", "10", "sliding velocity of the plate", "--velocity"},
              {t + "pressure", "number", "[0, σ_m,N]", "Pa", "1e8", "normal pressure on the plate", "--pressure"},
              {t + "sliding_distance", "number", "> 0", "m", "box x", "sliding distance", "--slide"},
              {t + "settle_distance", "number", "> 0", "m", "2 d0", "loading at rest (damped) before sliding, for the time the plate takes to slide this far", ""},
              {t + "settle_damping", "number", "[0, 1]", "1", "0.1", "global damping while settling, in c_c (6.64)", ""},
              {t + "track_distance", "number", "≥ d0", "m", "2 d0", "slide between updates of the rolling body", ""},
              {t + "time_step", "number", "(0, 1)", "1", "0.1", "time step in Δt_c", ""},
              {t + "record_every", "integer", "≥ 1", "1", "200", "steps per history sample", ""},
              {t + "seed", "integer", "[0, 4294967295]", "1", "1", "seed of the amorphous SiO2", "--seed"},
              {t + "relax_tolerance", "number", "(0, 0.01)", "1", "1e-4", "stress tolerance of the relaxation, in E", ""},
              {t + "max_relax_steps", "integer", "≥ 0", "1", "20000", "relaxation step limit", ""},
              {t + "dump_every", "integer", "≥ 0", "1", "5000", "steps between OVITO dump frames (0: none)", ""}});
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
