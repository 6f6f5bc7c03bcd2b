// The numerical wear maps of rough contacts (thesis ch. 5, Fig. 5.6–5.7) over
// [wearmap.rough]: number of particles and wear volume over (p̃_N, d*/L),
// mean and standard deviation over S random surfaces, the invalid region
// flagged, and each curve's maximum read off its smoothed version (§5.2).
// Outputs: wearmap_rough.h5 (+ .xdmf), wearmap_rough.csv (per pixel),
// _particles.csv (every particle), _curves.csv and _peaks.csv (Fig. 5.7), PNGs.
// With naive_pixels > 0 it also times the naive baseline (one full solve per
// candidate) against the fast model on a few pixels (summary field `baseline`).
#include <chrono>
#include <cmath>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wear_map_output.hpp"
#include "wearscale/core/output_set.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/core/progress.hpp"
#include "wearscale/core/task_farm.hpp"
#include "wearscale/coupling/palette.hpp"
#include "wearscale/coupling/plots.hpp"
#include "wearscale/io/checkpoint.hpp"
#include "wearscale/io/csv.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/io/xdmf.hpp"
#include "wearscale/studies/study.hpp"
#include "wearscale/studies/wearmap_keys.hpp"
#include "wearscale/wear/rough_wear_map.hpp"
#include "wearscale/wear/wear_curves.hpp"

namespace wearscale::studies {

const KeyTable<WearmapRoughKeys>& wearmap_rough_keys() {
  using K = WearmapRoughKeys;
  using wear::EnergyReleaseMethod;
  static const auto table =
      KeyTable<K>()
          .integer("n", [](K& k) -> std::size_t& { return k.map.surface.n; }, Range::closed(16, 4096),
                   "grid points per side (§5.3: 512)")
          .flag("--n")
          .integer("seeds", &K::seeds, Range::closed(1, 1000), "random surfaces to average, seeds 1…S")
          .flag("--seeds")
          .number("hurst", [](K& k) -> double& { return k.map.surface.hurst; }, Range::open_closed(0.0, 1.0),
                  "Hurst exponent H")
          .flag("--hurst")
          .number("q_l", [](K& k) -> double& { return k.map.surface.k_l; }, Range::at_least(1.0),
                  "q_l in units of 2π/L (= q_r)")
          .flag("--ql")
          .number("q_s", [](K& k) -> double& { return k.map.surface.k_s; }, Range::at_least(1.0),
                  "q_s in units of 2π/L")
          .computed_default([](const K& k) { return static_cast<double>(k.map.surface.n) / 8.0; }, "n/8")
          .allowed("[q_l, n/2]")
          .flag("--qs")
          .then([](const Config& c, K& k) {
            const auto& surface = k.map.surface;
            if (!(surface.k_l <= surface.k_s && surface.k_s <= static_cast<double>(surface.n) / 2.0))
              throw c.error(c.has("q_s") ? "q_s" : "q_l",
                            fmt::format("not allowed with q_l = {}, q_s = {} and n = {}", surface.k_l, surface.k_s,
                                        surface.n),
                            fmt::format("1 ≤ q_l ≤ q_s ≤ n/2 = {} (in 2π/L; q_s defaults to n/8)", surface.n / 2));
          })
          .interval("loads", &K::loads, Range::open(0.0, 1.0), units::dimensionless, "p̃_N (5.1)",
                    "normalized loads p̃_N (5.1), evenly spaced")
          .flag("--loads")
          .integer("n_loads", &K::n_loads, Range::closed(1, 1000), "points along p̃_N")
          .flag("--n-loads")
          .interval("dstar_over_l", &K::dstar_over_l, Range::positive(), units::dimensionless, "d*/L (4.35)",
                    "critical diameters d*/L (4.35), geometric")
          .flag("--dstar-over-l")
          .integer("n_dstar", &K::n_dstar, Range::closed(1, 1000), "points along d*/L")
          .flag("--n-dstar")
          .number("nu", [](K& k) -> double& { return k.map.surface.poisson; }, Range::open_closed(-1.0, 0.5),
                  "Poisson's ratio ν")
          .flag("--nu")
          .number("tensile_strength", [](K& k) -> double& { return k.map.tensile_strength; }, Range::positive(),
                  "σ_m/σ_j of the crack criterion (4.25)")
          .flag("--tensile-strength")
          .number("spot", [](K& k) -> double& { return k.map.spot; }, Range::closed(0.0, 1.0),
                  "crack sites within this fraction of each micro-contact's peak edge stress (1: every edge past σ_m)")
          .flag("--spot")
          .number("invalid_diameter", [](K& k) -> double& { return k.map.invalid_diameter; },
                  Range::open_closed(0.0, 1.0), "pixels whose mean largest particle is ≥ this × L are invalid")
          .flag("--invalid-diameter")
          .choice("energy_balance", [](K& k) -> bool& { return k.map.options.cumulative; },
                  std::vector<std::pair<std::string, bool>>{{"cumulative", true}, {"per_particle", false}},
                  "cumulative balance, or each particle pays for itself")
          .flag("--per-particle", "per_particle")
          .choice("method", [](K& k) -> EnergyReleaseMethod& { return k.map.options.method; },
                  std::vector<std::pair<std::string, EnergyReleaseMethod>>{{"fast", EnergyReleaseMethod::Fast},
                                                                           {"naive", EnergyReleaseMethod::Naive}},
                  "energy release: fast, or one full solve per candidate (the slow baseline)")
          .flag("--naive", "naive")
          .integer("naive_pixels", &K::naive_pixels, Range::closed(0, 1000),
                   "also time the naive baseline against the fast model on K pixels of the first seed (middle d*)")
          .flag("--naive-pixels")
          .integer("naive_max_solves", &K::naive_max_solves, Range::non_negative(),
                   "stop each naive pixel after this many solves and extrapolate its time (0: run it through)")
          .flag("--naive-max-solves");
  return table;
}

namespace {

namespace fs = std::filesystem;
namespace oi = coupling::okabe_ito;

std::vector<double> linear(std::pair<double, double> r, std::size_t k) {
  std::vector<double> v(k);
  for (std::size_t i = 0; i < k; ++i)
    v[i] = k == 1 ? r.first : r.first + (r.second - r.first) * static_cast<double>(i) / static_cast<double>(k - 1);
  return v;
}

std::vector<double> geometric(std::pair<double, double> r, std::size_t k) {
  std::vector<double> v(k);
  for (std::size_t i = 0; i < k; ++i)
    v[i] = k == 1 ? r.first : r.first * std::pow(r.second / r.first, static_cast<double>(i) / static_cast<double>(k - 1));
  return v;
}

// Viridis (perceptually uniform, readable in grey and by the colour-blind) for the maps; Okabe & Ito's
// palette (palette.hpp) for the curves.
const char* const kViridis = "set palette defined (0 '#440154', 1 '#482878', 2 '#3E4989', 3 '#31688E', 4 '#26828E', "
                             "5 '#1F9E89', 6 '#35B779', 7 '#6DCD59', 8 '#B4DE2C', 9 '#FDE725')\n";
const char* const kCurveColours[] = {oi::blue, oi::vermillion, oi::bluish_green, oi::reddish_purple,
                                     oi::orange, oi::sky_blue, oi::black};

// The PNG and PDF loop around a figure's commands.
std::string both_formats(const std::string& body) {
  return "do for [FORMAT in \"png pdf\"] {\n"
         "if (FORMAT eq \"png\") { set terminal pngcairo size 1000,760 font \"sans,11\" } "
         "else { set terminal pdfcairo size 7in,5.32in font \"sans,9\" }\n"
         "set output name.\".\".FORMAT\n" +
         body + "unset output\n}\n";
}

// Fig. 5.6: one map (column `col` of the pixel CSV `csv`, a file name) over (p̃_N, d*/L), invalid pixels
// crossed. Texts: 1 title, 2 table, 3 column, 4 log scale (1/0), 5-8 x and y ranges, 9 the pixels' size.
coupling::Figure map_figure(const std::string& name, const std::string& csv, int col, const std::string& title,
                            bool log_scale, const std::vector<double>& loads, const std::vector<double>& dstars) {
  const std::size_t nl = loads.size(), nd = dstars.size();
  const double ps = 60.0 / static_cast<double>(std::max(nl, nd));
  const double dx = nl > 1 ? 0.5 * (loads.back() - loads.front()) / double(nl - 1) : 0.5 * loads.front();
  const double fy = nd > 1 ? std::pow(dstars.back() / dstars.front(), 0.5 / double(nd - 1)) : 1.5;
  coupling::Figure f{name, "", {}, {csv}};
  f.add("title", title);
  f.add("table", csv);
  f.add("column", col);
  f.add("log scale", log_scale ? 1.0 : 0.0);
  f.add("x min", loads.front() - dx);
  f.add("x max", loads.back() + dx);
  f.add("y min", dstars.front() / fy);
  f.add("y max", dstars.back() * fy);
  f.add("pixel size", ps);
  f.script = both_formats(
      std::string("col = int(given_number(3))\nlog_scale = int(given_number(4))\nps = given_number(9)\n"
                  "set title given_text(1) noenhanced\nset xlabel \"normalized load p̃_N (5.1)\" noenhanced\n"
                  "set ylabel \"d*/L (4.35), crossed: invalid\" noenhanced\nset logscale y\n"
                  "set xrange [given_number(5):given_number(6)]\nset yrange [given_number(7):given_number(8)]\n"
                  "if (log_scale) { set logscale cb; set format cb \"10^{%L}\" }\n") +
      kViridis +
      "set key off\n"
      "plot given_text(2) using 1:2:(log_scale ? (column(col) > 0 ? column(col) : NaN) : column(col)) with points pt 5 "
      "ps ps lc palette, \\\n"
      "  given_text(2) using 1:(column(9) > 0.5 ? NaN : column(2)) with points pt 2 ps 0.6*ps lc rgb \"black\"\n");
  return f;
}

// Fig. 5.7: curves against p̃_N at every `step`-th d*, mean ± sd, invalid
// points cut; the number of particles also smoothed (dashed, §5.2; a count,
// drawn from 0 up: the filter's undershoot below 0 is not drawn). Texts: 1
// table, 2 volume (1/0), 3 the number of curves m, then per curve its first
// column and its d*/L.
coupling::Figure curves_figure(const std::string& name, const std::string& csv, const std::vector<double>& dstars,
                               bool volume) {
  const std::size_t nd = dstars.size(), step = std::max<std::size_t>(1, nd / 5);
  coupling::Figure f{name, "", {}, {csv}};
  f.add("table", csv);
  f.add("volume", volume ? 1.0 : 0.0);
  const std::size_t m_index = f.add("curves", 0.0);
  std::size_t m = 0;
  for (std::size_t d = 0; d < nd; d += step, ++m) {
    f.add("first column", static_cast<double>(6 * d));
    f.add("d*/L", dstars[d]);
  }
  f.texts[m_index - 1].second = fmt::format("{}", m);
  std::string colours;
  for (const char* c : kCurveColours) colours += (colours.empty() ? "" : " ") + std::string(c);
  // Columns per d*: count, sd, volume, sd, valid, smoothed count (after p_N_tilde).
  f.script = both_formats(
      "colours = \"" + colours + "\"\ncolour(c) = word(colours, (c - 1) % words(colours) + 1)\n" +
      "file = given_text(1)\nvolume = int(given_number(2))\nm = int(given_number(3))\nbase(c) = int(given_number(3 + 2*c - 1))\n"
      "dstar(c) = given_number(3 + 2*c)\noff = volume ? 4 : 2\nmax(a, b) = a > b ? a : b\n"
      "set title (volume ? \"Wear volume (Fig. 5.7b)\" : \"Number of particles (Fig. 5.7a; dashed: Savitzky-Golay, "
      "3/11)\")\n"
      "set xlabel \"normalized load p̃_N (5.1)\" noenhanced\n"
      "set ylabel (volume ? \"wear volume V / L^3\" : \"number of particles\")\n"
      "if (volume) { set logscale y; set format y \"10^{%L}\" } else { set yrange [0:*] }\n"
      "set grid\nset offsets graph 0.03, graph 0.03, 0, 0\nset key top left noenhanced Left reverse opaque\n"
      "plot for [c=1:m] file using 1:(column(6 + base(c)) > 0.5 ? column(off + base(c)) : NaN):(column(off + 1 + "
      "base(c))) with yerrorlines lw 1.5 pt 7 ps 0.8 lc rgb colour(c) title sprintf(\"d*/L = %.3g\", dstar(c)), \\\n"
      "  for [c=1:(volume ? 0 : m)] file using 1:(column(6 + base(c)) > 0.5 ? max(0, column(7 + base(c))) : NaN) "
      "with lines dt 2 lw 1.5 lc rgb colour(c) notitle\n");
  return f;
}

// The naive baseline on a few pixels (first seed, loads spread over the axis, middle d*), against the fast
// model on the same pixels. The naive run stops after `max_solves` solves; its time per pixel is then
// extrapolated as (time per solve) × (the solves it needs: every candidate the fast run evaluated or bounded,
// i.e. examined and not blocked by a recorded particle, plus one update per particle).
nlohmann::json naive_baseline(const wear::RoughWearMapSpec& spec, std::size_t naive_pixels, std::size_t max_solves) {
  const std::size_t nl = spec.loads.size(), nd = spec.critical_diameters.size();
  wear::RoughContactSeries series(spec.surface, spec.seeds.front());
  const double nu = spec.surface.poisson;
  wear::ShearedJunctions j{1.0, 1.0 / (2.0 * (1.0 + nu)), nu, spec.tensile_strength, spec.spot};
  const double dstar = spec.critical_diameters[nd / 2];
  double setup_s = 0.0, fast_s = 0.0, naive_s = 0.0, naive_est = 0.0;
  std::size_t naive_solves = 0, examined = 0, pixels = 0, truncated = 0;
  bool same = true;
  const std::size_t k = std::min(naive_pixels, nl);
  for (std::size_t i = 0; i < k; ++i) {
    const std::size_t l = k == 1 ? nl / 2 : i * (nl - 1) / (k - 1);
    const auto cmap = series.at_load(spec.loads[l]);
    const auto s0 = std::chrono::steady_clock::now();
    const wear::DetachmentModel model(cmap, j);
    const auto t1 = std::chrono::steady_clock::now();
    wear::DetachmentOptions fast = spec.options, slow = spec.options;
    fast.method = wear::EnergyReleaseMethod::Fast;
    slow.method = wear::EnergyReleaseMethod::Naive;
    slow.max_solves = max_solves;
    const auto rf = model.detach(dstar, fast);
    const auto t2 = std::chrono::steady_clock::now();
    const auto rn = model.detach(dstar, slow);
    const auto t3 = std::chrono::steady_clock::now();
    setup_s += std::chrono::duration<double>(t1 - s0).count();
    fast_s += std::chrono::duration<double>(t2 - t1).count();
    const double ns = std::chrono::duration<double>(t3 - t2).count();
    naive_s += ns;
    naive_solves += rn.solves;
    examined += rf.examined - rf.blocked;
    if (rn.truncated) {
      ++truncated;
      naive_est += ns / static_cast<double>(std::max<std::size_t>(rn.solves, 1)) *
                   static_cast<double>(rf.examined - rf.blocked + rf.particles.size());
    } else {
      naive_est += ns;
      same = same && rf.particles.size() == rn.particles.size();
    }
    ++pixels;
  }
  return {{"pixels", pixels},
          {"critical_diameter", dstar},
          {"setup_seconds_per_pixel", setup_s / double(pixels)},
          {"fast_seconds_per_pixel", fast_s / double(pixels)},
          {"naive_seconds_per_pixel", naive_est / double(pixels)},
          {"naive_measured_seconds", naive_s},
          {"naive_truncated_pixels", truncated},
          {"ratio", naive_est / fast_s},
          {"naive_solves", naive_solves},
          {"naive_solves_needed", examined},
          {"same_particle_counts", same}};
}

// One surface on the wire between ranks (CBOR: doubles travel as their 8 bytes, so the map is the serial one bit for bit).
std::string to_message(const wear::SurfaceWearMap& f) {
  nlohmann::json particles = nlohmann::json::array();
  for (const auto& p : f.particles) particles.push_back({p.seed, p.load_index, p.dstar_index, p.x, p.y, p.diameter});
  const nlohmann::json j = {{"index", f.index}, {"count", f.count}, {"volume", f.volume}, {"largest", f.largest},
                            {"fraction", f.contact_fraction}, {"particles", particles},
                            {"seconds", {f.contact_seconds, f.setup_seconds, f.detach_seconds}},
                            {"work", {f.candidates, f.energy_evaluations, f.solves}}};
  const auto bytes = nlohmann::json::to_cbor(j);
  return {bytes.begin(), bytes.end()};
}

wear::SurfaceWearMap from_message(const std::string& text) {
  const auto j = nlohmann::json::from_cbor(text);
  wear::SurfaceWearMap f;
  f.index = j.at("index").get<std::size_t>();
  f.count = j.at("count").get<std::vector<double>>();
  f.volume = j.at("volume").get<std::vector<double>>();
  f.largest = j.at("largest").get<std::vector<double>>();
  f.contact_fraction = j.at("fraction").get<std::vector<double>>();
  for (const auto& p : j.at("particles"))
    f.particles.push_back({p[0].get<std::uint64_t>(), p[1].get<std::size_t>(), p[2].get<std::size_t>(),
                           p[3].get<double>(), p[4].get<double>(), p[5].get<double>()});
  const auto& t = j.at("seconds");
  f.contact_seconds = t[0].get<double>(), f.setup_seconds = t[1].get<double>(), f.detach_seconds = t[2].get<double>();
  const auto& w = j.at("work");
  f.candidates = w[0].get<std::size_t>(), f.energy_evaluations = w[1].get<std::size_t>(), f.solves = w[2].get<std::size_t>();
  return f;
}

// The surfaces as the tasks of a farm: over the ranks of an mpirun job (one
// task per seed, each on one rank with its threads), in order on one rank;
// each surface kept in the run's task store as it finishes, so a resumed run,
// a shard (--task K/N) or a merge computes only what is missing. Collective;
// rank 0 gets the map, the others nothing. `identity` (rank 0): the case's
// fingerprint; `tasks` (rank 0): seed, rank, threads and wall time of each
// surface; `progress` (one rank): after each (seed, p̃_N).
std::optional<wear::RoughWearMap> map_over_ranks(const wear::RoughWearMapSpec& spec, const std::string& identity,
                                                 nlohmann::json& tasks,
                                                 const std::function<void(std::size_t)>& progress = {}) {
  mpi::FarmOptions options;
  options.label = "wearmap rough surfaces";
  options.show_progress = mpi::size() > 1;  // one rank: the contacts' progress instead
  options.stop = [] { return interrupt_requested(); };
  options.identity = [&](std::size_t s) { return fmt::format("wearmap/rough {} seed {}", identity, spec.seeds[s]); };
  options.name = [&](std::size_t s) { return fmt::format("seed {}", spec.seeds[s]); };
  const std::size_t nl = spec.loads.size();
  const auto outcome = mpi::farm(
      spec.seeds.size(),
      [&](std::size_t s) {
        const auto each_load = [&](std::size_t done, std::size_t) {
          if (progress) progress(s * nl + done);
        };
        return to_message(wear::rough_wear_map_surface(spec, s, each_load));
      },
      options);
  if (outcome.not_run > 0) throw Interrupted("wearmap rough: stopped by a signal");
  if (!mpi::is_root()) {
    if (outcome.failed > 0) throw mpi::TasksFailed("", false);
    return std::nullopt;
  }
  std::vector<wear::SurfaceWearMap> surfaces;
  std::vector<std::string> failed;
  tasks = nlohmann::json::array();
  for (std::size_t s = 0; s < outcome.results.size(); ++s) {
    const auto& r = outcome.results[s];
    tasks.push_back({{"seed", spec.seeds[s]}, {"rank", r.rank}, {"threads", r.threads}, {"seconds", r.seconds}});
    if (r.status == mpi::TaskResult::Status::Done)
      surfaces.push_back(from_message(r.text));
    else
      failed.push_back(fmt::format("seed {} (rank {}): {}", spec.seeds[s], r.rank, r.text));
  }
  if (!failed.empty())  // a map needs every surface
    throw mpi::TasksFailed(fmt::format("wearmap rough: {} of {} surfaces failed: {}", failed.size(), spec.seeds.size(),
                                       fmt::join(failed, "; ")),
                           true);
  return wear::combine_surfaces(spec, surfaces);
}

class WearmapRough final : public Study {
 public:
  std::string name() const override { return "wearmap/rough"; }
  std::string summary() const override {
    return "Numerical wear maps of rough contacts (ch. 5, Fig. 5.6–5.7): number of particles and wear volume over "
           "(p̃_N, d*/L), averaged over surfaces";
  }
  std::string default_case_name() const override { return "wearmap"; }
  std::string default_output_dir() const override { return "out/wearmap-rough"; }  // each map its own folder
  Schema schema() const override;
  std::vector<std::string> prepare(Config& cfg) override;
  void run(const Config& cfg, RunContext& context) override;
  // Under mpirun: the surfaces (seeds) over the ranks, rank 0 writing.
  bool distributed() const override { return true; }
  bool has_ensembles() const override { return true; }
  void run_other_rank(const Config&) override {
    nlohmann::json unused;
    map_over_ranks(spec_, {}, unused);
  }

 private:
  wear::RoughWearMapSpec spec_;  // the resolved [wearmap.rough]
  std::size_t naive_pixels_ = 0, naive_max_solves_ = 0;
};

Schema WearmapRough::schema() const { return wearmap_rough_keys().schema("wearmap.rough"); }

std::vector<std::string> WearmapRough::prepare(Config& cfg) {
  const std::string k = "wearmap.rough.";
  WearmapRoughKeys keys;
  wearmap_rough_keys().read(cfg.section("wearmap.rough"), keys);
  cfg.reject_unknown_keys();
  spec_ = keys.map;
  const auto& surface = spec_.surface;
  const std::size_t seeds = keys.seeds, n_loads = keys.n_loads, n_dstar = keys.n_dstar;
  const auto loads = keys.loads, dstar = keys.dstar_over_l;
  const bool per_particle = !spec_.options.cumulative;
  const bool naive = spec_.options.method == wear::EnergyReleaseMethod::Naive;
  naive_pixels_ = keys.naive_pixels;
  naive_max_solves_ = keys.naive_max_solves;

  spec_.seeds.clear();
  for (std::size_t s = 1; s <= seeds; ++s) spec_.seeds.push_back(s);
  spec_.loads = linear(loads, n_loads);
  spec_.critical_diameters = geometric(dstar, n_dstar);
  wear::validate(spec_);
  // The resolved values, defaults included, for summary.json and the HDF5 files.
  for (const auto& [key, value] :
       {std::pair<const char*, std::string>{"n", fmt::format("{}", surface.n)}, {"seeds", fmt::format("{}", seeds)},
        {"hurst", toml_number(surface.hurst)}, {"q_l", toml_number(surface.k_l)}, {"q_s", toml_number(surface.k_s)},
        {"loads", toml_range(loads)}, {"n_loads", fmt::format("{}", n_loads)}, {"dstar_over_l", toml_range(dstar)},
        {"n_dstar", fmt::format("{}", n_dstar)}, {"nu", toml_number(surface.poisson)},
        {"tensile_strength", toml_number(spec_.tensile_strength)}, {"spot", toml_number(spec_.spot)},
        {"invalid_diameter", toml_number(spec_.invalid_diameter)},
        {"energy_balance", per_particle ? "\"per_particle\"" : "\"cumulative\""},
        {"method", naive ? "\"naive\"" : "\"fast\""}, {"naive_pixels", fmt::format("{}", naive_pixels_)},
        {"naive_max_solves", fmt::format("{}", naive_max_solves_)}})
    record(cfg, k + key, value);
  return {};
}

void WearmapRough::run(const Config& cfg, RunContext& context) {
  const wear::RoughWearMapSpec& spec = spec_;
  const fs::path& out = context.output_dir();
  const std::size_t nl = spec.loads.size(), nd = spec.critical_diameters.size();
  const double contacts = static_cast<double>(spec.seeds.size() * nl);
  // (Under mpirun the farm shows the surfaces done instead.)
  Progress bar = context.show_progress() && mpi::size() == 1 ? Progress("wearmap rough", contacts, "contacts")
                                                             : Progress::silent(contacts);
  const auto t0 = std::chrono::steady_clock::now();
  nlohmann::json tasks;
  const auto map = *map_over_ranks(spec, case_fingerprint(cfg.to_json()), tasks,
                                   [&](std::size_t done) { bar.update(double(done)); });
  bar.finish();
  if (!tasks.is_null()) context.note("tasks", tasks);
  const double total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const nlohmann::json baseline =
      naive_pixels_ > 0 ? naive_baseline(spec, naive_pixels_, naive_max_solves_) : nlohmann::json();

  const fs::path h5 = out / "wearmap_rough.h5", xmf = out / "wearmap_rough.xdmf", csv = out / "wearmap_rough.csv",
                 pcsv = out / "wearmap_rough_particles.csv", ccsv = out / "wearmap_rough_curves.csv",
                 kcsv = out / "wearmap_rough_peaks.csv";
  std::vector<double> load, dstar, cm, cs, vm, vs, lm, fr, valid;
  for (const auto& p : map.pixels) {
    load.push_back(p.load), dstar.push_back(p.critical_diameter), cm.push_back(p.count_mean);
    cs.push_back(p.count_sd), vm.push_back(p.volume_mean), vs.push_back(p.volume_sd);
    lm.push_back(p.largest_mean), fr.push_back(p.contact_fraction), valid.push_back(p.valid ? 1.0 : 0.0);
  }
  const std::vector<std::string> names = {"p_N_tilde", "dstar_over_L", "count_mean", "count_sd", "volume_mean",
                                          "volume_sd", "largest_diameter_mean", "contact_fraction", "valid"};
  const std::vector<std::span<const double>> columns = {load, dstar, cm, cs, vm, vs, lm, fr, valid};
  std::vector<double> ps, pl, pd, px, py, pdia;
  for (const auto& p : map.particles) {
    ps.push_back(double(p.seed)), pl.push_back(spec.loads[p.load_index]);
    pd.push_back(spec.critical_diameters[p.dstar_index]), px.push_back(p.x), py.push_back(p.y);
    pdia.push_back(p.diameter);
  }
  const std::vector<std::string> pnames = {"seed", "p_N_tilde", "dstar_over_L", "x_over_L", "y_over_L",
                                           "diameter_over_L"};
  const std::vector<std::span<const double>> pcols = {ps, pl, pd, px, py, pdia};
  // Fig. 5.7: each curve's maximum read off its smoothed version (§5.2).
  std::vector<wear::CurveMaximum> peaks;
  std::vector<double> peak_dstar, peak_load, peak_count, peak_raw, peak_found;
  for (std::size_t d = 0; d < nd; ++d) {
    peaks.push_back(wear::curve_maximum(map, d));
    const auto& c = peaks.back();
    double raw = 0.0;
    for (std::size_t l = 0; l < nl; ++l)
      if (map.pixel(l, d).valid) raw = std::max(raw, map.pixel(l, d).count_mean);
    peak_dstar.push_back(spec.critical_diameters[d]);
    peak_load.push_back(c.found ? c.load : std::nan(""));
    peak_count.push_back(c.found ? c.count : std::nan(""));
    peak_raw.push_back(c.found ? raw : std::nan(""));
    peak_found.push_back(c.found ? 1.0 : 0.0);
  }
  const std::vector<std::string> peak_names = {"dstar_over_L", "p_N_tilde_at_max", "count_max_smoothed",
                                               "count_max_raw", "found"};
  const std::vector<std::span<const double>> peak_cols = {peak_dstar, peak_load, peak_count, peak_raw, peak_found};
  const std::string peak_note =
      fmt::format("Fig. 5.7: maximum of each curve (number of particles against p_N_tilde) over its valid pixels, on "
                  "the curve smoothed by a Savitzky-Golay filter of degree {} on {} points (thesis §5.2: 3 on 11); "
                  "count_max_raw: the unsmoothed maximum; found = 0 where no pixel is valid",
                  peaks.front().degree, peaks.front().window);
  XdmfSidecar sidecar(Grid2D(nl, nd, static_cast<double>(nl), static_cast<double>(nd)));
  {
    H5Writer w(h5);
    w.write_series("/axes/p_N_tilde", spec.loads);
    w.write_table("/curve_maxima", peak_names, peak_cols);
    w.set_attribute("/curve_maxima", "description", peak_note);
    w.write_series("/axes/dstar_over_L", spec.critical_diameters);
    w.write_table("/pixels", names, columns);
    w.write_table("/particles", pnames, pcols);
    const Grid2D g(nl, nd, 1.0, 1.0);
    auto field = [&](const std::vector<double>& v, const std::string& path) {
      RealField f(g);
      for (std::size_t k = 0; k < v.size(); ++k) f[k] = v[k];
      w.write_field(path, f);
      w.set_attribute(path, "axes", "rows: p_N_tilde (/axes/p_N_tilde), columns: dstar_over_L (/axes/dstar_over_L)");
    };
    field(cm, "/maps/count_mean"), field(cs, "/maps/count_sd"), field(vm, "/maps/volume_mean");
    field(vs, "/maps/volume_sd"), field(valid, "/maps/valid");
    w.set_attribute("/", "description", "numerical wear maps of rough contacts (thesis ch. 5, Fig. 5.6); rows p_N_tilde, "
                                        "columns dstar_over_L; lengths in units of L, volumes in L^3");
    w.set_attribute("/", "hurst", spec.surface.hurst);
    w.set_attribute("/", "q_l", spec.surface.k_l);
    w.set_attribute("/", "q_s", spec.surface.k_s);
    w.set_attribute("/", "n", double(spec.surface.n));
    w.set_attribute("/", "seeds", double(spec.seeds.size()));
    w.set_attribute("/", "poisson", spec.surface.poisson);
    w.set_attribute("/", "tensile_strength_over_sigma_j", spec.tensile_strength);
    w.set_attribute("/", "energy_balance", spec.options.cumulative ? "cumulative" : "per particle");
    w.set_attribute("/", "case_toml", cfg.to_toml());
    // ParaView: the maps on the (p̃_N, d*/L) pixel grid in index space, pixel
    // (l, d) at X = l, Y = d as in the PNGs (the axes' values are in /axes).
    sidecar.add(w, {{"/maps/count_mean", "count_mean"}, {"/maps/count_sd", "count_sd"},
                    {"/maps/volume_mean", "volume_mean"}, {"/maps/volume_sd", "volume_sd"}, {"/maps/valid", "valid"}});
    w.commit();
  }
  sidecar.write(xmf, h5);
  // Every column is a ratio, a count or a length / L, a volume / L^3: dimensionless.
  const auto plain = [](const std::vector<std::string>& n) { return std::vector<std::string>(n.size(), "1"); };
  write_csv(csv, names, columns, plain(names),
            {"wearscale wearmap rough: mean and sample sd over seeds; valid = 0 where the mean "
             "largest particle exceeds the invalid diameter (crossed in Fig. 5.6)"});
  write_csv(pcsv, pnames, pcols, plain(pnames), {"every detached particle of every seed and pixel; lengths / L"});
  {
    std::vector<std::string> cn = {"p_N_tilde"};
    std::vector<std::vector<double>> cv(1 + 6 * nd, std::vector<double>(nl));
    for (std::size_t l = 0; l < nl; ++l) cv[0][l] = spec.loads[l];
    for (std::size_t d = 0; d < nd; ++d) {
      const std::string tag = fmt::format("{:.4g}", spec.critical_diameters[d]);
      for (const char* c : {"count_", "count_sd_", "volume_", "volume_sd_", "valid_", "count_smoothed_"})
        cn.push_back(c + tag);
      for (std::size_t l = 0; l < nl; ++l) {
        const auto& p = map.pixel(l, d);
        cv[1 + 6 * d][l] = p.count_mean, cv[2 + 6 * d][l] = p.count_sd, cv[3 + 6 * d][l] = p.volume_mean;
        cv[4 + 6 * d][l] = p.volume_sd, cv[5 + 6 * d][l] = p.valid ? 1.0 : 0.0;
        cv[6 + 6 * d][l] = peaks[d].smoothed[l];
      }
    }
    std::vector<std::span<const double>> spans(cv.begin(), cv.end());
    write_csv(ccsv, cn, spans, plain(cn),
              {"Fig. 5.7: per d*/L, mean and sd of the number of particles and wear volume / L^3, and the number "
               "of particles smoothed as in §5.2 (wearmap_rough_peaks.csv: the maximum of each curve)"});
    write_csv(kcsv, peak_names, peak_cols, plain(peak_names), {peak_note});
  }
  for (const auto& f : {h5, xmf, csv, pcsv, ccsv, kcsv}) context.add_file(f);
  // Fig. 5.6 maps and Fig. 5.7 curves (column 3: count, 5: volume).
  const std::string pixels_csv = csv.filename().string(), curves_csv = ccsv.filename().string();
  context.add_figure(map_figure("wearmap_rough_count", pixels_csv, 3, "Number of particles (Fig. 5.6a)", false,
                                spec.loads, spec.critical_diameters));
  context.add_figure(map_figure("wearmap_rough_volume", pixels_csv, 5, "Wear volume / L^3 (Fig. 5.6b)", true,
                                spec.loads, spec.critical_diameters));
  context.add_figure(curves_figure("wearmap_rough_curves_count", curves_csv, spec.critical_diameters, false));
  context.add_figure(curves_figure("wearmap_rough_curves_volume", curves_csv, spec.critical_diameters, true));

  std::size_t invalid = 0;
  double max_count = 0.0;
  for (const auto& p : map.pixels) {
    invalid += p.valid ? 0 : 1;
    max_count = std::max(max_count, p.count_mean);
  }
  const double pixels = static_cast<double>(nl * nd);
  context.report("pixels", pixels, "1", "map pixels (p̃_N × d*/L)");
  context.report("invalid_fraction", double(invalid) / pixels, "1", "share of pixels with particles ≥ the invalid size");
  context.report("max_count", max_count, "1", "largest mean number of particles on the map");
  double max_smoothed = 0.0;
  for (const auto& c : peaks)
    if (c.found) max_smoothed = std::max(max_smoothed, c.count);
  context.report("max_count_smoothed", max_smoothed, "1",
                 "largest maximum of the Fig. 5.7 curves read on their smoothed version (§5.2)");
  context.report("seconds", total_seconds, "s", "wall time of the map (all seeds)");
  context.report("seconds_per_pixel", total_seconds / (pixels * double(spec.seeds.size())), "s",
                 "wall time per pixel and seed");
  context.report("contact_seconds", map.contact_seconds, "s", "BEM contact solves");
  context.report("model_setup_seconds", map.setup_seconds, "s", "crack stresses, candidates, u of the full loading");
  context.report("detach_seconds", map.detach_seconds, "s", "detachment procedure over all pixels and seeds");
  context.report("candidates", double(map.candidates), "1", "candidate particles summed over seeds and loads");
  context.report("energy_evaluations", double(map.energy_evaluations), "1", "ΔE_el (5.3) evaluated in full");
  if (!baseline.is_null()) {
    context.report("naive_ratio", baseline["ratio"].get<double>(), "1",
                   "naive (one solve per candidate) over fast time per pixel");
    context.report("naive_seconds_per_pixel", baseline["naive_seconds_per_pixel"].get<double>(), "s",
                   "naive baseline (extrapolated on truncated pixels)");
    context.report("fast_seconds_per_pixel", baseline["fast_seconds_per_pixel"].get<double>(), "s",
                   "fast, same pixels (the shared set-up apart)");
    context.report("setup_seconds_per_pixel", baseline["setup_seconds_per_pixel"].get<double>(), "s",
                   "candidates, crack stresses and u of the full loading, shared by both");
    context.note("baseline", baseline);
  }
  // The sample points of the axes.
  context.note("axes", {{"p_N_tilde", spec.loads}, {"dstar_over_L", spec.critical_diameters}});
}

}  // namespace
}  // namespace wearscale::studies

WEARSCALE_STUDY(WearmapRough)
