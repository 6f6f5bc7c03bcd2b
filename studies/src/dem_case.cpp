#include "dem_case.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/coupling/plots.hpp"
#include "wearscale/dem/contact_law.hpp"
#include "wearscale/dem/engine.hpp"
#ifdef WEARSCALE_DEM_LAMMPS
#include "wearscale/dem/lammps_engine.hpp"
#endif
#include "wearscale/dem/patch_test.hpp"
#include "wearscale/io/csv.hpp"
#include "wearscale/io/material_definitions.hpp"
#include "wearscale/materials/material.hpp"

namespace wearscale::studies {

using namespace dem;

// ---- [dem] ------------------------------------------------------------------

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

void read_contact_law(const Config& root, std::string& law, double& friction) {
  const Config c = root.section("dem");
  law = c.string_or("law", "cohesive");
  const auto known = contact_law_names();
  if (std::find(known.begin(), known.end(), law) == known.end())
    throw c.error("law", fmt::format("unknown DEM contact law '{}'", law), fmt::format("{}", fmt::join(known, ", ")));
  if (law == "hooke") friction = c.number_or("friction", 0.5, Range::non_negative());
}

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

void require_cohesive_law(const Config& root, const char* study) {
  std::string law;
  double friction = 0.0;
  read_contact_law(root, law, friction);
  if (law != "cohesive")
    throw root.section("dem").error("law", fmt::format("the {} measures the cohesive law's strengths", study), "cohesive");
}

Schema material_keys(const MaterialKeys& keys) {
  return {{"dem.material", "string", "", "", keys.fallback, keys.materials, "--material"},
          {"dem.poisson", "number", "(-1, 0.25]", "1", "the material's", "target Poisson's ratio", keys.poisson_flag},
          {"dem.restitution", "number", "(0, 1]", "1", "the material's", "coefficient of restitution", ""},
          {"dem.scaling_exponent", "number", "[0, 1]", "1", "0.5", "size-scaling exponent s of (6.57)",
           keys.scaling_exponent_flag},
          {"dem.law", "choice", fmt::format("{}", fmt::join(contact_law_names(), " | ")), "", "cohesive",
           "contact law between the particles (contact_law.hpp)", ""},
          {"dem.friction", "number", "≥ 0", "1", "0.5", "Coulomb μ of the hooke law", ""},
          {"dem.engine", "choice", std::string(engine_choices), "", "wearscale",
           "the engine that integrates the particles (LAMMPS: over every rank under mpirun)", ""}};
}

// ---- The keys several studies name alike ------------------------------------

double read_time_step(const Config& c) { return c.number_or("time_step", 0.1, Range::open(0.0, 1.0)); }
KeySpec time_step_key(const std::string& table) {
  return {table + ".time_step", "number", "(0, 1)", "1", "0.1", "time step in Δt_c", ""};
}

std::uint64_t read_seed(const Config& c) {
  return static_cast<std::uint64_t>(c.integer_or("seed", 1, Range::closed(0, 4294967295.0)));
}
KeySpec seed_key(const std::string& table, const std::string& doc) {
  return {table + ".seed", "integer", "[0, 4294967295]", "1", "1", doc, "--seed"};
}

double read_d0(const Config& c) { return c.number("d0", Range::positive(), units::length); }
KeySpec d0_key(const std::string& table) {
  return {table + ".d0", "number", "> 0", "m", "", "mode of the particle diameters", "--d0"};
}

double read_largest(const Config& c, double d0) {
  return c.number_or("largest", 1.25 * d0, Range::at_least(d0), units::length);
}
KeySpec largest_key(const std::string& table, const std::string& doc) {
  return {table + ".largest", "number", "≥ d0", "m", "1.25 d0", doc, ""};
}

double read_sliding_velocity(const Config& c) {
  return c.number_or("velocity", 10.0, Range::open(0.0, 1000.0), units::velocity);
}
KeySpec sliding_velocity_key(const std::string& table, const std::string& doc) {
  return {table + ".velocity", "number", "(0, 1000)", "m/s", "10", doc, "--velocity"};
}

double read_pressure(const Config& c, double fallback, const CohesiveMaterial& m) {
  return c.number_or("pressure", fallback, Range::closed(0.0, m.tensile_strength), units::pressure);
}
KeySpec pressure_key(const std::string& table, const std::string& fallback, const std::string& doc) {
  return {table + ".pressure", "number", "[0, σ_m,N]", "Pa", fallback, doc, "--pressure"};
}

double read_sliding_distance(const Config& c, double fallback) {
  return c.number_or("sliding_distance", fallback, Range::positive(), units::length);
}
KeySpec sliding_distance_key(const std::string& table, const std::string& fallback) {
  return {table + ".sliding_distance", "number", "> 0", "m", fallback, "sliding distance", "--slide"};
}

std::optional<Vec3> read_box(const Config& c) {
  if (!c.has("box")) return std::nullopt;
  const auto b = c.numbers("box", Range::positive(), units::length);
  if (b.size() != 3) throw c.error("box", fmt::format("{} values", b.size()), "three lengths [x, y, z]");
  return Vec3{b[0], b[1], b[2]};
}
KeySpec box_key(const std::string& table, const std::string& fallback, const std::string& doc) {
  return {table + ".box", "list", "three lengths > 0", "m", fallback, doc, ""};
}

double read_wall_thickness(const Config& c) { return c.number_or("wall_thickness", 1.5, Range::closed(1.0, 10.0)); }
KeySpec wall_thickness_key(const std::string& table, const std::string& doc) {
  return {table + ".wall_thickness", "number", "[1, 10]", "1", "1.5", doc, ""};
}

double read_clearance(const Config& c) { return c.number_or("clearance", 0.25, Range::closed_open(0.0, 1.0)); }
KeySpec clearance_key(const std::string& table, const std::string& doc) {
  return {table + ".clearance", "number", "[0, 1)", "1", "0.25", doc, ""};
}

long read_record_every(const Config& c) { return c.integer_or("record_every", 200, Range::at_least(1)); }
KeySpec record_every_key(const std::string& table) {
  return {table + ".record_every", "integer", "≥ 1", "1", "200", "steps per history sample", ""};
}

double read_relax_tolerance(const Config& c) { return c.number_or("relax_tolerance", 1e-4, Range::open(0.0, 1e-2)); }
KeySpec relax_tolerance_key(const std::string& table) {
  return {table + ".relax_tolerance", "number", "(0, 0.01)", "1", "1e-4", "stress tolerance of the relaxation, in E", ""};
}

long read_max_relax_steps(const Config& c) { return c.integer_or("max_relax_steps", 20000, Range::at_least(0)); }
KeySpec max_relax_steps_key(const std::string& table) {
  return {table + ".max_relax_steps", "integer", "≥ 0", "1", "20000", "relaxation step limit", ""};
}

long read_dump_every(const Config& c, long fallback) { return c.integer_or("dump_every", fallback, Range::at_least(0)); }
KeySpec dump_every_key(const std::string& table, long fallback) {
  return {table + ".dump_every", "integer", "≥ 0", "1", std::to_string(fallback),
          "steps between OVITO dump frames (0: none)", ""};
}

// ---- The sliding cell -------------------------------------------------------

void read_sliding_cell(const Config& root, const Config& c, SlidingCellSpec& cell) {
  cell.material = dem_material(root);
  read_contact_law(root, cell.law, cell.friction);
  // [dem] history: "touching" carries tangential histories over neighbour
  // rebuilds for touching pairs only, as LAMMPS did in the thesis' runs.
  cell.history_of_touching_pairs_only =
      root.section("dem").choice_or("history", "kept", {"kept", "touching"}) == "touching";
  cell.engine = read_engine(root);
  cell.d0 = read_d0(c);
  cell.largest = read_largest(c, cell.d0);
  cell.velocity = read_sliding_velocity(c);
  cell.pressure = read_pressure(c, 0.5e9, cell.material);
  cell.time_step = read_time_step(c);
  cell.settle_distance = c.number_or("settle_distance", cell.d0, Range::non_negative(), units::length);
  cell.wall_damping = c.number_or("wall_damping", 0.0, Range::closed(0.0, 1.0));
  cell.wall_thickness = read_wall_thickness(c);
  cell.record_every = read_record_every(c);
  cell.seed = read_seed(c);
  cell.relax_tolerance = read_relax_tolerance(c);
  cell.max_relax_steps = read_max_relax_steps(c);
}

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

Schema sliding_keys(const std::string& table, const std::string& slide_default) {
  return {{"dem.history", "choice", "kept | touching", "", "kept",
           "tangential histories over neighbour rebuilds: kept for every pair in reach (6.4), or for touching pairs "
           "only (the thesis' LAMMPS runs)",
           ""},
          d0_key(table),
          sliding_velocity_key(table),
          pressure_key(table, "5e8"),
          sliding_distance_key(table, slide_default),
          seed_key(table),
          largest_key(table),
          time_step_key(table),
          {table + ".settle_distance", "number", "≥ 0", "m", "d0",
           "loading at rest before sliding, for the time the wall takes to slide this far", ""},
          {table + ".wall_damping", "number", "[0, 1]", "1", "0",
           "damping of the pressed wall's normal motion, in the critical damping", ""},
          wall_thickness_key(table),
          record_every_key(table),
          relax_tolerance_key(table),
          max_relax_steps_key(table),
          {table + ".depth", "number", "≥ largest", "m", "3.5 d0", "cell depth W (periodic)", ""},
          dump_every_key(table, 2000)};
}

// ---- Around a study's run ---------------------------------------------------

struct EngineRanks::Served {
#ifdef WEARSCALE_DEM_LAMMPS
  LammpsServedRun run;
#endif
};

EngineRanks::EngineRanks([[maybe_unused]] const std::string& engine) {
#ifdef WEARSCALE_DEM_LAMMPS
  if (engine == "lammps") served_ = std::make_unique<Served>();
#endif
}

EngineRanks::~EngineRanks() = default;

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

std::unique_ptr<Progress> progress_bar(const std::string& name, long planned, const RunCheckpoints& hooks) {
  auto bar = std::make_unique<Progress>(name, static_cast<double>(planned));
  if (hooks.from != nullptr) bar->start_at(static_cast<double>(hooks.from->step));
  return bar;
}

void SlidingDumps::operator()(const SlidingCell& cell, long step, long planned, const std::string& name,
                              const RunCheckpoints& hooks) {
  if (!bar) bar = progress_bar(name, planned, hooks);
  if (writer.frames() == 0) write(cell);
  bar->update(static_cast<double>(step));
  if (every > 0 && (step % every < cell_record_every || step == planned)) write(cell);
}

void SlidingDumps::write(const SlidingCell& cell) {
  const auto worn = cell.worn_flags();
  writer.write(cell.engine(), {{"worn", worn}});
}

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

// ---- DemStudy ---------------------------------------------------------------

std::vector<std::string> DemStudy::prepare(Config& inputs) {
  engine_ = read_engine(inputs);
  return {};
}

void DemStudy::run_other_rank(const Config&) {
#ifdef WEARSCALE_DEM_LAMMPS
  serve_lammps_engines();
#endif
}

std::string DemStudy::default_output_dir() const {
  std::string leaf = name().substr(name().find('/') + 1);
  std::replace(leaf.begin(), leaf.end(), '_', '-');
  return "out/dem-" + leaf;
}

void DemStudy::finish(const nlohmann::json& outputs, RunContext& context, const std::string& history) {
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

}  // namespace wearscale::studies
