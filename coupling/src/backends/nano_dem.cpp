// nano/dem: the junction study of §7.1.1 run in the DEM of chapter 6 for each
// interface the pin meets (pin material on top, counterface below), fitted
// to the model of §7.1.2 — the same InterfaceLaw (p_crit, μ0, A/A0 = p_N/p_crit,
// wear rate) as nano/analytic, with the runs and the fit as provenance.
// DEM particles take E, ν, γ, σ_m,N, ρ, η from the material record and σ_m,T
// from the molecular strength law at the working pressure. Runs are cached on
// disk by the SHA-256 of their inputs and shared within the process, so a
// sweep computes each junction once.
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <future>
#include <map>
#include <mutex>
#include <optional>
#include <thread>
#include <tuple>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "wearscale/coupling/scale.hpp"
#include "wearscale/io/key_table.hpp"
#include "backends/case_materials.hpp"
#include "backends/junction_messages.hpp"
#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/cache_folder.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/task_farm.hpp"
#ifdef WEARSCALE_DEM_LAMMPS
#include "wearscale/dem/lammps_engine.hpp"
#endif
#include "wearscale/core/task_store.hpp"
#include "wearscale/core/utc_time.hpp"
#include "wearscale/core/worker_pool.hpp"
#include "wearscale/coupling/plots.hpp"
#include "wearscale/dem/junction_strength.hpp"
#include "wearscale/io/csv.hpp"
#include "wearscale/materials/junction_model.hpp"
#include "wearscale/materials/material.hpp"
#include "wearscale/md/result_cache.hpp"

namespace wearscale::coupling {

namespace {

namespace fs = std::filesystem;
using dem::JunctionStrengthResult;

constexpr const char* kJunctionTask = "nano/dem junction";  // a run on any rank of an mpirun job
using dem::JunctionStrengthSpec;

constexpr const char* cache_version = "wearscale-dem-junction-v3";  // v3: thin cells, the tangential cap of the thesis code

// --- One junction run, as stored in the cache --------------------------------

nlohmann::json to_json(const JunctionStrengthResult& r) {
  std::vector<double> s, t, n;
  const double area = r.length * r.depth;
  for (const auto& h : r.history) {
    s.push_back(h.sliding);
    t.push_back(h.tangential_force / area);
    n.push_back(h.normal_force / area);
  }
  return {{"length", r.length}, {"depth", r.depth}, {"height", r.height}, {"gap", r.gap},
          {"particles", r.particles}, {"junction_particles", r.junction_particles}, {"time_step", r.time_step},
          {"steps", r.steps}, {"initial_contact_ratio", r.initial_contact_ratio},
          {"loaded_contact_ratio", r.loaded_contact_ratio}, {"final_contact_ratio", r.final_contact_ratio},
          {"peak_tangential", r.peak_tangential}, {"steady_tangential", r.steady_tangential}, {"normal", r.normal},
          {"rolling_rate", r.rolling_rate}, {"rigid_residual", r.rigid_residual}, {"outcome", r.verdict()},
          {"history", {{"sliding", s}, {"p_T", t}, {"p_N", n}}}};
}

JunctionStrengthResult from_json(const nlohmann::json& j) {
  JunctionStrengthResult r;
  r.length = j.at("length");
  r.depth = j.at("depth");
  r.height = j.at("height");
  r.gap = j.at("gap");
  r.particles = j.at("particles");
  r.junction_particles = j.at("junction_particles");
  r.time_step = j.at("time_step");
  r.steps = j.at("steps");
  r.initial_contact_ratio = j.at("initial_contact_ratio");
  r.loaded_contact_ratio = j.at("loaded_contact_ratio");
  r.final_contact_ratio = j.at("final_contact_ratio");
  r.peak_tangential = j.at("peak_tangential");
  r.steady_tangential = j.at("steady_tangential");
  r.normal = j.at("normal");
  r.rolling_rate = j.at("rolling_rate");
  r.rigid_residual = j.at("rigid_residual");
  const std::string outcome = j.at("outcome");
  r.outcome = outcome == "flattened" ? JunctionStrengthResult::Outcome::Flattened
              : outcome == "detached" ? JunctionStrengthResult::Outcome::Detached
                                      : JunctionStrengthResult::Outcome::Sheared;
  const auto& h = j.at("history");
  const auto s = h.at("sliding").get<std::vector<double>>(), t = h.at("p_T").get<std::vector<double>>(),
             n = h.at("p_N").get<std::vector<double>>();
  const double area = r.length * r.depth;
  for (std::size_t k = 0; k < s.size() && k < t.size() && k < n.size(); ++k) {
    dem::JunctionSample x;
    x.sliding = s[k];
    x.tangential_force = t[k] * area;
    x.normal_force = n[k] * area;
    r.history.push_back(x);
  }
  return r;
}

std::string material_text(const dem::CohesiveMaterial& m) {
  return fmt::format("{}|{:.17g}|{:.17g}|{:.17g}|{:.17g}|{:.17g}|{:.17g}|{:.17g}|{:.17g}", m.name, m.young, m.poisson,
                     m.tensile_strength, m.shear_strength, m.surface_energy, m.restitution, m.density,
                     m.scaling_exponent);
}

// Every input that determines a run's result.
std::string run_key(const JunctionStrengthSpec& s) {
  const auto& c = s.cell;
  const std::string spec = fmt::format(
      "d0={:.17g} L={} H={} B={} gap={:.17g} wall={:.17g} D/L={:.17g} p={:.17g} v={:.17g} dt={:.17g} settle={:.17g} "
      "slide={:.17g} steady={:.17g} every={}{}{}{}",
      c.d0, c.length, c.height, c.depth, c.gap, c.wall_thickness, s.contact_ratio, s.pressure, s.velocity, s.time_step,
      s.settle_distance, s.sliding_distance, s.steady_from, s.record_every,
      s.arrangement == dem::Arrangement::Amorphous
          ? fmt::format(" amorphous seed={} relax={:.17g}/{}", s.seed, s.relax_tolerance, s.max_relax_steps)
          : std::string(),
      s.history_of_touching_pairs_only ? " history=touching" : "",
      s.engine == "wearscale" ? std::string() : " engine=" + s.engine);
  return md::cache_key({cache_version, WEARSCALE_VERSION, material_text(s.top), material_text(s.bottom), spec});
}

// The runs of this process by key (a sweep's runs share them), backed by the
// on-disk cache. The first caller of a key computes it; others wait for it.
class JunctionRuns {
 public:
  static JunctionRuns& instance() {
    static JunctionRuns runs;
    return runs;
  }
  struct Claim {
    std::shared_future<JunctionStrengthResult> result;
    std::shared_ptr<std::promise<JunctionStrengthResult>> mine;  // set: this caller computes it
  };
  Claim claim(const std::string& key) {
    std::lock_guard lock(mutex_);
    if (auto it = runs_.find(key); it != runs_.end()) return {it->second, nullptr};
    auto promise = std::make_shared<std::promise<JunctionStrengthResult>>();
    auto future = promise->get_future().share();
    runs_.emplace(key, future);
    return {future, promise};
  }
  void forget(const std::string& key) {
    std::lock_guard lock(mutex_);
    runs_.erase(key);
  }

 private:
  std::mutex mutex_;
  std::map<std::string, std::shared_future<JunctionStrengthResult>> runs_;
};

// --- The keys of [scale.nano] with backend = "dem" ---------------------------

// What the keys fill: the junction run every (D/L, p_N) pair starts from
// (its cell and loading, with dem::JunctionStrengthSpec's defaults), the
// runs to make, and how the particles are taken from the materials.
struct NanoDemKeys {
  JunctionStrengthSpec run;
  std::vector<double> contact_ratios{0.25, 1.0};
  std::vector<double> pressures{1e9, 2e9, 4e9};
  std::vector<std::string> amorphous;  ///< materials built amorphous; {"none"}: none
  std::string strength = "dynamic";
  std::optional<double> working_pressure;
  double scaling_exponent = 0.5;
  double restitution = 0.9;
  bool clamp_poisson = true;
  double max_poisson = 0.25;
  bool cache = true;
  std::string cache_dir;  ///< "": the user cache folder's dem/
  int jobs = 1;
};

// A case that lists some materials turned off by --set: amorphous = "none".
void none_means_no_material(const Config&, NanoDemKeys& k) {
  if (k.amorphous.size() == 1 && k.amorphous.front() == "none") k.amorphous.clear();
}

void check_engine([[maybe_unused]] const Config& c, [[maybe_unused]] NanoDemKeys& k) {
#ifndef WEARSCALE_DEM_LAMMPS
  if (k.run.engine == "lammps")
    throw c.error("engine", "this build has no LAMMPS engine (it is built when CMake finds Debian's liblammps-dev, "
                  "option WEARSCALE_DEM_LAMMPS)", "wearscale");
#endif
}

// Each junction at least one particle wide.
void check_contact_ratios(const Config& c, NanoDemKeys& k) {
  const int length = k.run.cell.length;
  for (double r : k.contact_ratios)
    if (r * length < 1.0)
      throw c.error("contact_ratios",
                    fmt::format("D/L = {:g} is less than one particle of the {}-particle cell", r, length),
                    fmt::format("[{:.3g}, 1]", 1.0 / length));
}

const KeyTable<NanoDemKeys>& nano_dem_keys() {
  using K = NanoDemKeys;
  using Cell = dem::JunctionCell;
  const auto cell = [](auto member) { return [member](K& k) -> auto& { return k.run.cell.*member; }; };
  const auto run = [](auto member) { return [member](K& k) -> auto& { return k.run.*member; }; };
  static const auto table =
      KeyTable<K>()
          // The cell (§7.1.1) and the loading.
          .number("d0", cell(&Cell::d0), Range::positive(), units::length, "particle diameter d0")
          .integer("length", cell(&Cell::length), Range::closed(6, 400),
                   "cell length L in d0 (the periodic sliding direction)")
          .integer("height", cell(&Cell::height), Range::closed(4, 400), "cell height in HCP double rows of √3 d0")
          .integer("depth", cell(&Cell::depth), Range::closed(1, 50),
                   "cell depth in HCP cells of √(8/3) d0 (1: the thesis' 2.4 nm)")
          .number("gap", cell(&Cell::gap), Range::open(0.0, 0.8),
                  "height of the gap the junction bridges, as a fraction of the cell height")
          .number("wall_thickness", cell(&Cell::wall_thickness), Range::closed(0.5, 10.0),
                  "in d0: the particles this close to the top and bottom faces form the rigid walls")
          .number("velocity", run(&JunctionStrengthSpec::velocity), Range::positive(), units::velocity,
                  "sliding velocity of the top wall")
          .number("time_step", run(&JunctionStrengthSpec::time_step), Range::open(0.0, 1.0),
                  "time step in Δt_c (6.6)")
          .number("settle_distance", run(&JunctionStrengthSpec::settle_distance), Range::non_negative(),
                  "loading before sliding: the time to slide this many L at the velocity")
          .number("sliding_distance", run(&JunctionStrengthSpec::sliding_distance), Range::positive(),
                  "sliding distance in L")
          .number("steady_from", run(&JunctionStrengthSpec::steady_from), Range::closed_open(0.0, 1.0),
                  "the steady window: the slide after this fraction of it")
          .integer("record_every", run(&JunctionStrengthSpec::record_every), Range::at_least(1),
                   "steps per sample of a run's history")
          .choice("history", run(&JunctionStrengthSpec::history_of_touching_pairs_only),
                  std::vector<std::pair<std::string, bool>>{{"kept", false}, {"touching", true}},
                  "tangential histories over neighbour rebuilds: every contact keeps its own (6.4), or touching "
                  "pairs only, as LAMMPS did in the thesis' runs")
          .choice("engine", run(&JunctionStrengthSpec::engine), std::vector<std::string>{"wearscale", "lammps"},
                  "the engine of the junction runs: wearscale's own, or LAMMPS (a build with liblammps-dev), each "
                  "run on the rank the farm hands it to")
          .then(check_engine)
          .names("amorphous", &K::amorphous,
                 "materials whose interfaces are built amorphous (§6.2.2) instead of on the HCP lattice of §7.1.1; "
                 "\"none\": none")
          .then(none_means_no_material)
          .integer("seed", run(&JunctionStrengthSpec::seed), Range::closed(0, 4294967295.0),
                   "seed of the amorphous samples")
          .allowed("[0, 4294967295]")
          .numbers("contact_ratios", &K::contact_ratios, Range::open_closed(0.0, 1.0), units::dimensionless,
                   "junction sizes D/L, one run each under each pressure")
          .then(check_contact_ratios)
          .numbers("pressures", &K::pressures, Range::non_negative(), units::pressure,
                   "normal pressures p_N of the runs")
          // DEM particles from the material records and the molecular strengths.
          .choice("strength", &K::strength, std::vector<std::string>{"dynamic", "peak"},
                  "σ_m,T of the particles: σ_dyn or σ_max of the molecular law at the working pressure")
          .optional_number("working_pressure", &K::working_pressure, Range::positive(), units::pressure,
                           "pressure at which the molecular law gives σ_m,T")
          .fallback("p_crit of the molecular law (7.5)")
          .number("scaling_exponent", &K::scaling_exponent, Range::closed(0.0, 1.0),
                  "scaling exponent of the particles' strengths (6.62)")
          .number("restitution", &K::restitution, Range::open_closed(0.0, 1.0),
                  "coefficient of restitution η of a material whose record has none")
          .boolean("clamp_poisson", &K::clamp_poisson,
                   "model a material with ν above max_poisson with ν = max_poisson (false: refuse it)")
          .number("max_poisson", &K::max_poisson, Range::open_closed(-1.0, 0.25),
                  "the largest ν modelled: pair forces give ν ≤ 1/4 (6.52), where the tangential spring vanishes")
          .boolean("cache", &K::cache, "keep each run in the cache and reuse it")
          .string("cache_dir", &K::cache_dir, "folder of the cached runs")
          .fallback("~/.cache/wearscale/dem ($WEARSCALE_CACHE/dem)")
          .integer("jobs", &K::jobs, Range::closed(1, 256), "junction runs side by side (threads)")
          .computed_default([](const K&) { return std::max(1, omp_get_max_threads()); },
                            "the OpenMP threads (OMP_NUM_THREADS)");
  return table;
}

// --- The backend --------------------------------------------------------------

struct Interface {
  std::string pin, counterface;
  std::string pair() const { return pin + "/" + counterface; }
  std::string tag() const { return pin + "-" + counterface; }
};

class NanoDem final : public Scale {
 public:
  static inline const Ports ports{{{Quantity::ShearStrength, "pin, disc, layer"}},
                                  {{Quantity::InterfaceLaw, "pin/disc"}, {Quantity::InterfaceLaw, "pin/layer"}}};

  explicit NanoDem(const ScaleSetup& setup) : provenance_(setup.provenance()) {
    const Config& root = setup.root;
    const Config& c = setup.section;
    library_ = material_library(root);
    case_materials(root, library_);  // checks every name
    pin_ = root.string("materials.pin");
    std::vector<std::string> counterfaces{root.string("materials.disc")};
    if (root.has("materials.layer.material")) {
      const std::string layer = root.string("materials.layer.material");
      if (layer != counterfaces.front()) counterfaces.push_back(layer);
    }
    for (const auto& cf : counterfaces) interfaces_.push_back({pin_, cf});
    e_star_ = materials::effective_modulus(library_.get(pin_), library_.get(pin_));

    NanoDemKeys k;
    nano_dem_keys().read(c, k);
    base_ = k.run;
    ratios_ = k.contact_ratios;
    pressures_ = k.pressures;
    for (const auto& name : k.amorphous) {
      if (!library_.contains(name))
        throw c.error("amorphous", fmt::format("no material '{}'", name), "names of the case's materials, or \"none\"");
      amorphous_.push_back(name);
    }
    strength_ = k.strength;
    working_pressure_ = k.working_pressure;
    scaling_exponent_ = k.scaling_exponent;
    restitution_ = k.restitution;
    clamp_poisson_ = k.clamp_poisson;
    max_poisson_ = k.max_poisson;
#ifdef WEARSCALE_DEM_LAMMPS
    if (base_.engine == "lammps") dem::register_lammps_engine();
#endif
    for (const auto& name : case_materials(root, library_)) {
      const auto& m = library_.get(name);
      if (m.poisson > max_poisson_ && !clamp_poisson_)
        throw c.error("clamp_poisson",
                      fmt::format("material '{}' has ν = {} and the DEM models ν ≤ max_poisson = {} (the pair force "
                                  "gives ν ≤ 1/4, (6.52))",
                                  name, m.poisson, max_poisson_),
                      fmt::format("true (model it with ν = {})", max_poisson_));
    }
    cache_ = k.cache;
    cache_dir_ = k.cache_dir.empty() ? cache_folder("dem") : expand_home(k.cache_dir);
    jobs_ = k.jobs;
    // Under mpirun any rank may be handed a junction run (run_all).
    mpi::register_task_kind(kJunctionTask, [](const std::string& spec) {
      return to_message(dem::run_junction_strength(spec_from_message(spec)));
    });
  }

  bool farms_ensembles() const override { return true; }

  std::vector<Key> consumes() const override {
    std::vector<Key> out{{ports.consumes[0].what, pin_}};
    for (const auto& i : interfaces_)
      if (i.counterface != pin_) out.push_back({ports.consumes[0].what, i.counterface});
    return out;
  }
  std::vector<Key> provides() const override {
    std::vector<Key> out;
    for (const auto& i : interfaces_) out.push_back({ports.provides[0].what, i.pair()});
    return out;
  }

  void run(Exchange& exchange, RunContext& ctx) override {
    for (const auto& i : interfaces_) {
      const auto top = particle_material(exchange, i.pin);
      const auto bottom = particle_material(exchange, i.counterface);
      std::vector<JunctionStrengthSpec> specs;
      for (double ratio : ratios_)
        for (double p : pressures_) {
          JunctionStrengthSpec s = base_;
          s.top = top.material;
          s.bottom = bottom.material;
          s.arrangement = amorphous(i) ? dem::Arrangement::Amorphous : dem::Arrangement::Hcp;
          s.contact_ratio = ratio;
          s.pressure = p;
          specs.push_back(s);
        }
      const auto results = run_all(specs, i.pair(), ctx);

      std::vector<dem::JunctionPoint> points;
      for (const auto& r : results) {
        const auto& [s, res, cached] = r;
        points.push_back({s.pressure, res.initial_contact_ratio, res.loaded_contact_ratio, res.final_contact_ratio,
                          res.peak_tangential, res.steady_tangential,
                          res.outcome == JunctionStrengthResult::Outcome::Flattened});
      }
      const auto fit = dem::fit_junction_law(points);
      materials::InterfaceLaw law;
      law.pair = i.pair();
      law.governing = top.material.shear_strength <= bottom.material.shear_strength ? i.pin : i.counterface;
      law.p_crit = fit.p_crit;
      law.mu0 = fit.mu0;
      if (!(law.p_crit > 0.0) || !std::isfinite(law.p_crit) || !(law.mu0 > 0.0) || !std::isfinite(law.mu0))
        throw NumericalError("nano/dem", 0, "junction law fit of " + law.pair,
                             fmt::format("p_crit = {:g} Pa, μ0 = {:g}: no usable fit from {} runs", law.p_crit, law.mu0,
                                         fit.runs));

      const std::string tag = i.tag();
      ctx.report("p_crit_" + tag, law.p_crit, "Pa",
                 fmt::format("critical pressure of the {} junctions (7.6) from the DEM contact ratios ({})", law.pair,
                             fit.p_crit_source));
      ctx.report("mu0_" + tag, law.mu0, "1",
                 fmt::format("steady friction coefficient of {}: DEM sliding strength {:.3g} GPa / p_crit (9.13)", law.pair,
                             fit.steady_strength / 1e9));
      ctx.report("steady_slope_" + tag, materials::steady_slope_rms(law.p_crit, e_star_), "1",
                 "steady RMS slope √(2π) p_crit/E* with E* of the pin material (9.17)");
      ctx.report("d_star_" + tag,
                 materials::critical_size(library_.get(law.governing), law.p_crit,
                                          materials::JunctionGeometry::FlatCircular),
                 "m",
                 "critical junction size 12πγG/((2−ν)σ²) of " + law.governing +
                     " at the junction strength σ = p_crit, as nano/analytic (4.35)");
      ctx.report("sigma_fit_" + tag, fit.shear_strength, "Pa",
                 fmt::format("σ of peak p_T = (A/A0) σ (7.9) over the {} DEM runs", fit.runs));
      const nlohmann::json fit_json = {
          {"shear_strength", fit.shear_strength}, {"shear_strength_relative_rms", fit.shear_strength_rms},
          {"full_contact_peak", fit.full_contact_peak}, {"steady_strength", fit.steady_strength},
          {"p_crit", fit.p_crit}, {"p_crit_relative_rms", fit.p_crit_rms}, {"p_crit_source", fit.p_crit_source},
          {"mu0", fit.mu0}, {"mu0_direct", fit.mu0_direct}, {"runs", fit.runs}, {"crushed", fit.crushed},
          {"flattened", fit.flattened}, {"flattened_into_full_contact", fit.saturated}};
      write_outputs(ctx, i, results, fit);

      Provenance p = provenance_;
      p.parameters["particles"] = {{"top", top.description}, {"bottom", bottom.description}};
      p.parameters["arrangement"] = amorphous(i) ? "amorphous (§6.2.2)" : "HCP lattice (§7.1.1)";
      p.parameters["fit"] = fit_json;
      nlohmann::json runs = nlohmann::json::array();
      for (const auto& [s, res, cached] : results)
        runs.push_back({{"contact_ratio", s.contact_ratio}, {"pressure", s.pressure}, {"key", run_key(s)},
                        {"cached", cached}, {"initial_contact_ratio", res.initial_contact_ratio},
                        {"loaded_contact_ratio", res.loaded_contact_ratio},
                        {"final_contact_ratio", res.final_contact_ratio}, {"peak_p_T", res.peak_tangential},
                        {"steady_p_T", res.steady_tangential}, {"outcome", res.verdict()}});
      p.parameters["runs"] = runs;
      exchange.put<Quantity::InterfaceLaw>(law.pair, law, std::move(p));
    }
  }

 private:
  struct ParticleMaterial {
    dem::CohesiveMaterial material;
    nlohmann::json description;
  };
  using Run = std::tuple<JunctionStrengthSpec, JunctionStrengthResult, bool>;

  bool amorphous(const Interface& i) const {
    return std::find(amorphous_.begin(), amorphous_.end(), i.pin) != amorphous_.end() ||
           std::find(amorphous_.begin(), amorphous_.end(), i.counterface) != amorphous_.end();
  }

  // The DEM targets of a material: its record, with σ_m,T = σ_dyn (or σ_max)
  // of the molecular law at the working pressure — p_crit of (7.5) unless
  // given: the local pressure of a sliding junction flattened to A_min (7.6).
  ParticleMaterial particle_material(const Exchange& exchange, const std::string& name) const {
    const auto& law = exchange.get<Quantity::ShearStrength>(name);
    const auto& record = library_.get(name);
    const double p_work = working_pressure_ ? *working_pressure_ : materials::critical_pressure(law);
    ParticleMaterial out;
    auto& m = out.material;
    m = dem::cohesive_material(record, scaling_exponent_, record.restitution ? *record.restitution : restitution_);
    m.shear_strength = strength_ == "dynamic" ? law.sigma_dyn(p_work) : law.sigma_max(p_work);
    const bool clamped = m.poisson > max_poisson_;
    if (clamped) m.poisson = max_poisson_;  // central pair forces: ν ≤ 1/4 (6.52)
    dem::require_modelled(m);
    out.description = {{"material", name}, {"young", m.young}, {"poisson", m.poisson},
                       {"poisson_record", record.poisson}, {"poisson_clamped", clamped},
                       {"tensile_strength", m.tensile_strength}, {"shear_strength", m.shear_strength},
                       {"shear_strength_from", fmt::format("{} of the molecular law at {:.4g} GPa ({})",
                                                           strength_ == "dynamic" ? "σ_dyn" : "σ_max", p_work / 1e9,
                                                           working_pressure_ ? "working_pressure" : "p_crit (7.5)")},
                       {"surface_energy", m.surface_energy}, {"density", m.density},
                       {"restitution", m.restitution}, {"restitution_from", record.restitution ? "record" : "restitution key"},
                       {"scaling_exponent", m.scaling_exponent}};
    return out;
  }

  // A junction run in messages and log names.
  static std::string junction_name(const std::string& pair, const JunctionStrengthSpec& spec) {
    return fmt::format("{} junction D/L = {:g} at p_N = {:.3g} GPa", pair, spec.contact_ratio, spec.pressure / 1e9);
  }

  // Runs (or reads) every junction, on jobs_ threads; each run is computed
  // once per process and once per cache. Under mpirun (a served run): the
  // runs not in the cache over the ranks instead, rank 0 writing the cache.
  std::vector<Run> run_all(const std::vector<JunctionStrengthSpec>& specs, const std::string& pair,
                           RunContext& ctx) const {
    mpi::TaskStore* const task_store = mpi::TaskStore::current();  // the run's: finished runs kept, kept ones taken
    if (mpi::ServedRun::active() || (task_store != nullptr && task_store->mode() != mpi::TaskStore::Mode::Keep))
      return run_over_ranks(specs, pair, ctx);
    std::vector<std::string> keys;
    for (const auto& s : specs) keys.push_back(run_key(s));
    std::vector<std::shared_future<JunctionStrengthResult>> futures(specs.size());
    std::vector<char> computed(specs.size(), 0);
    // At most the OpenMP threads of this run (one per run inside a sweep,
    // whose runs then share the junctions through JunctionRuns).
    WorkerOptions workers;
    workers.workers = static_cast<unsigned>(
        std::min({jobs_, std::max(1, omp_get_max_threads()), static_cast<int>(specs.size())}));
#ifdef WEARSCALE_DEM_LAMMPS
    // LAMMPS instances side by side need MPI on every thread (a process of
    // its own initialises it so); under mpirun, one after the other.
    if (base_.engine == "lammps" && !dem::lammps_engines_on_threads()) workers.workers = 1;
#endif
    workers.omp_threads = 1;
    run_on_workers(specs.size(), workers, [&](std::size_t k) {
      auto claim = JunctionRuns::instance().claim(keys[k]);
      futures[k] = claim.result;
      if (!claim.mine) return;  // another run of this process computes it
      try {
        const std::string identity = mpi::described_identity(kJunctionTask, to_message(specs[k]));
        if (auto kept = task_store != nullptr ? task_store->find(identity) : std::nullopt) {
          claim.mine->set_value(result_from_message(kept->text));  // finished before this run was stopped
          return;
        }
        if (auto hit = cached(cache_dir_ / (keys[k] + ".json"))) {
          claim.mine->set_value(*hit);
          return;
        }
        // Its own log, as a task of the farm keeps under mpirun.
        std::optional<log::TaskLog> task_log;
        if (task_store != nullptr) {
          const auto file = task_store->log_path(identity, junction_name(pair, specs[k]));
          std::error_code ec;
          fs::create_directories(file.parent_path(), ec);
          task_log.emplace(file);
          log::task_note(fmt::format("task started on rank 0 of 1, 1 thread(s), {}", utc_now()));
        }
        bool fresh = false;
        claim.mine->set_value(compute(specs[k], keys[k], pair, ctx, fresh));
        computed[k] = fresh ? 1 : 0;
        if (task_store != nullptr && fresh) task_store->keep(identity, to_message(claim.result.get()));
      } catch (...) {
        JunctionRuns::instance().forget(keys[k]);
        claim.mine->set_exception(std::current_exception());
      }
    });
    std::vector<Run> out;
    for (std::size_t k = 0; k < specs.size(); ++k) out.emplace_back(specs[k], futures[k].get(), computed[k] == 0);
    return out;
  }

  // The runs over the ranks of an mpirun job (the task farm), those in the
  // cache read here; a run that fails ends the scale as it would serially.
  // The summary's "tasks" list which rank ran each, on how many threads, for how long.
  std::vector<Run> run_over_ranks(const std::vector<JunctionStrengthSpec>& specs, const std::string& pair,
                                  RunContext& ctx) const {
    // Every run is a task of the farm (so that a shard's share does not move
    // with what the cache holds); those in the cache are kept in the run's
    // task store first, and the farm takes them from there.
    std::vector<std::optional<JunctionStrengthResult>> results(specs.size());
    std::vector<std::string> descriptions;
    std::vector<char> from_cache(specs.size(), 0);
    const mpi::TaskStore* task_store = mpi::TaskStore::current();
    for (std::size_t k = 0; k < specs.size(); ++k) {
      descriptions.push_back(to_message(specs[k]));
      results[k] = cached(cache_dir_ / (run_key(specs[k]) + ".json"));
      if (!results[k]) continue;
      from_cache[k] = 1;
      const std::string identity = mpi::described_identity(kJunctionTask, descriptions.back());
      if (task_store != nullptr && !task_store->find(identity)) task_store->keep(identity, to_message(*results[k]));
    }
    mpi::FarmOptions options;
    options.label = "nano/dem " + pair + " junctions";
    options.stop = [] { return interrupt_requested(); };
    options.name = [&](std::size_t k) { return junction_name(pair, specs[k]); };
    options.root_computes = base_.engine != "lammps";  // a LAMMPS instance runs on a rank's main thread
    const auto outcome = mpi::farm_described(kJunctionTask, descriptions, options);
    nlohmann::json tasks = ctx.notes().contains("tasks") ? ctx.notes()["tasks"] : nlohmann::json::array();
    for (std::size_t k = 0; k < specs.size(); ++k) {
      if (from_cache[k]) continue;
      const auto& r = outcome.results[k];
      const auto& spec = specs[k];
      if (r.status == mpi::TaskResult::Status::NotRun) throw Interrupted("nano/dem: junction runs");
      if (r.status == mpi::TaskResult::Status::Failed) {
        const std::string what = fmt::format("{} (rank {})", options.name(k), r.rank);
        if (r.numerical) throw NumericalError("nano/dem", 0, what, r.text);
        throw InputError(fmt::format("nano/dem: {}: {}", what, r.text));
      }
      results[k] = result_from_message(r.text);
      log::info("nano/dem: {} D/L = {:g}, p_N = {:.3g} GPa: peak p_T {:.3g} GPa ({}, rank {}, {:.1f} s)", pair,
                spec.contact_ratio, spec.pressure / 1e9, results[k]->peak_tangential / 1e9, results[k]->verdict(),
                r.rank, r.seconds);
      store(cache_dir_ / (run_key(spec) + ".json"), *results[k]);
      tasks.push_back({{"interface", pair}, {"contact_ratio", spec.contact_ratio}, {"pressure", spec.pressure},
                       {"rank", r.rank}, {"threads", r.threads}, {"seconds", r.seconds}});
    }
    ctx.note("tasks", std::move(tasks));
    std::vector<Run> out;
    for (std::size_t k = 0; k < specs.size(); ++k) out.emplace_back(specs[k], *results[k], from_cache[k] != 0);
    return out;
  }

  // A run's cache entry, if caching and it is there and readable.
  std::optional<JunctionStrengthResult> cached(const fs::path& entry) const {
    if (!cache_) return std::nullopt;
    std::error_code ec;
    if (!fs::is_regular_file(entry, ec)) return std::nullopt;
    try {
      std::ifstream in(entry);
      return from_json(nlohmann::json::parse(in));
    } catch (const std::exception& e) {
      log::warn("nano/dem: ignoring the unreadable cache entry {}: {}", entry.string(), e.what());
      return std::nullopt;
    }
  }

  // Writes a run's cache entry (atomically: readers see the whole entry or none), if caching.
  void store(const fs::path& entry, const JunctionStrengthResult& result) const {
    if (!cache_) return;
    std::error_code ec;
    fs::create_directories(cache_dir_, ec);
    if (ec)
      throw InputError(fmt::format("nano/dem: cannot create the cache folder {}: {}; set scale.nano.cache_dir or "
                                   "WEARSCALE_CACHE to a writable folder, or scale.nano.cache = false",
                                   cache_dir_.string(), ec.message()));
    write_file_atomically(entry, to_json(result).dump() + "\n");
  }

  JunctionStrengthResult compute(const JunctionStrengthSpec& spec, const std::string& key, const std::string& pair,
                                 RunContext& ctx, bool& fresh) const {
    const fs::path entry = cache_dir_ / (key + ".json");
    if (auto hit = cached(entry)) return *hit;
    log::info("nano/dem: {} junction D/L = {:g} at p_N = {:.3g} GPa ...", pair, spec.contact_ratio, spec.pressure / 1e9);
    // Checkpointed as its own owner in the run's checkpoint (several junctions
    // run side by side; the checkpointer is shared, hence the lock).
    const std::string owner = "nano/dem/" + key;
    dem::RunCheckpoints checkpoints;
    {
      std::lock_guard lock(checkpoint_mutex_);
      checkpoints.from = ctx.checkpoints().restored(owner);
    }
    if (checkpoints.from != nullptr)
      log::info("nano/dem: {} D/L = {:g} at p_N = {:.3g} GPa resumes at step {}", pair, spec.contact_ratio,
                spec.pressure / 1e9, checkpoints.from->step);
    checkpoints.at_sample = [&](long step, const std::function<CheckpointState()>& make) {
      std::lock_guard lock(checkpoint_mutex_);
      ctx.checkpoints().at_step(owner, step, make);
    };
    auto result = dem::run_junction_strength(spec, {}, checkpoints);
    fresh = true;
    log::info("nano/dem: {} D/L = {:g}, p_N = {:.3g} GPa: peak p_T {:.3g} GPa, steady {:.3g} GPa, A/A0 {:.2f} → {:.2f} ({})",
              pair, spec.contact_ratio, spec.pressure / 1e9, result.peak_tangential / 1e9,
              result.steady_tangential / 1e9, result.initial_contact_ratio, result.final_contact_ratio,
              result.verdict());
    store(entry, result);
    return result;
  }

  // junction_<tag>.csv, /nano/<tag> in run.h5, and p_T against p_N with the
  // model lines (7.9)-(7.10) when gnuplot is there.
  void write_outputs(RunContext& ctx, const Interface& i, const std::vector<Run>& runs,
                     const dem::JunctionLawFit& fit) const {
    std::vector<double> ratio, p_n, c0, cl, cf, peak, steady, normal, outcome, rolling, cached;
    for (const auto& [s, r, from_cache] : runs) {
      ratio.push_back(s.contact_ratio);
      p_n.push_back(s.pressure);
      c0.push_back(r.initial_contact_ratio);
      cl.push_back(r.loaded_contact_ratio);
      cf.push_back(r.final_contact_ratio);
      peak.push_back(r.peak_tangential);
      steady.push_back(r.steady_tangential);
      normal.push_back(r.normal);
      outcome.push_back(static_cast<double>(r.outcome));
      rolling.push_back(r.rolling_rate);
      cached.push_back(from_cache ? 1.0 : 0.0);
    }
    const std::vector<std::string> names{"D_over_L", "p_N", "A_over_A0_initial", "A_over_A0_loaded", "A_over_A0_final",
                                         "p_T_peak", "p_T_steady", "p_N_measured", "outcome", "rolling_rate", "cached"};
    const std::string group = "/nano/" + i.tag();
    const std::vector<std::string> units{"1", "Pa", "1", "1", "1", "Pa", "Pa", "Pa", "1", "1", "1"};
    ctx.h5().write_table(group + "/runs", names, {ratio, p_n, c0, cl, cf, peak, steady, normal, outcome, rolling, cached},
                         units);
    ctx.h5().set_attribute(group + "/runs", "outcome", "0 flattened, 1 sheared, 2 detached");
    ctx.h5().write_scalar(group + "/sigma_fit", fit.shear_strength, "Pa");
    ctx.h5().write_scalar(group + "/p_crit", fit.p_crit, "Pa");
    ctx.h5().write_scalar(group + "/mu0", fit.mu0, "1");
    const auto csv = ctx.output_dir() / ("junction_" + i.tag() + ".csv");
    write_csv(csv, names, {ratio, p_n, c0, cl, cf, peak, steady, normal, outcome, rolling, cached}, units,
              {fmt::format("nano/dem junction runs of {} (§7.1.1), SI units; outcome: 0 flattened, 1 sheared, 2 detached",
                           i.pair()),
               fmt::format("fit (§7.1.2): sigma = {:.6g} Pa (rel. RMS {:.3f}), sliding strength {:.6g} Pa, p_crit = {:.6g} Pa "
                           "({}, rel. RMS {:.3f}), mu0 = {:.6g}",
                           fit.shear_strength, fit.shear_strength_rms, fit.steady_strength, fit.p_crit,
                           fit.p_crit_source, fit.p_crit_rms, fit.mu0)});
    ctx.add_file(csv);
    ctx.add_figure(junction_strength_figure(
        "junction_" + i.tag(),
        fmt::format("{} junctions (§7.1.1) and the fitted model (7.9)-(7.10)\n{}, L = {:.3g} nm, d0 = {:.3g} nm, v = "
                    "{:.3g} m/s, slid {:.3g} L",
                    i.pair(), amorphous(i) ? "amorphous (§6.2.2)" : "HCP lattice",
                    runs.empty() ? 0.0 : std::get<1>(runs.front()).length * 1e9, base_.cell.d0 * 1e9, base_.velocity,
                    base_.sliding_distance),
        csv, ratios_, fit.shear_strength, fit.p_crit, runs.empty() ? 0.0 : std::get<1>(runs.front()).length,
        ctx.output_dir()));
  }

  Provenance provenance_;
  materials::MaterialLibrary library_;
  std::string pin_;
  std::vector<Interface> interfaces_;
  double e_star_ = 0.0;
  JunctionStrengthSpec base_;
  std::vector<double> ratios_, pressures_;
  std::vector<std::string> amorphous_;
  std::string strength_;
  std::optional<double> working_pressure_;
  double scaling_exponent_ = 0.5, restitution_ = 0.9;
  bool clamp_poisson_ = true, cache_ = true;
  double max_poisson_ = 0.25;
  fs::path cache_dir_;
  mutable std::mutex checkpoint_mutex_;  // junction runs save checkpoints from several threads
  int jobs_ = 1;
};

}  // namespace

WEARSCALE_BACKEND(nano_dem) {
  registry.add<NanoDem>("nano", "dem",
                        "sheared DEM junctions of §7.1.1 fitted to the model of §7.1.2: p_crit, μ0, A/A0 and wear "
                        "rate per interface, cached",
                        [] { return nano_dem_keys().schema("scale.nano"); });
}

}  // namespace wearscale::coupling
