// wearscale wearmap rough [CASE.toml] [--n N] [--seeds S] [--hurst H] [--ql QL] [--qs QS] [--loads MIN:MAX]
//                         [--n-loads K] [--dstar-over-l MIN:MAX] [--n-dstar K] [--nu NU] [--tensile-strength R]
//                         [--spot F] [--invalid-diameter F] [--per-particle] [--naive] [--naive-pixels K]
//                         [--set KEY=VALUE]... [--out DIR] [--json]
// The numerical wear maps of rough contacts (thesis ch. 5, Fig. 5.6–5.7):
// number of particles and wear volume over (p̃_N, d*/L), mean and standard
// deviation over S random surfaces, with the invalid region flagged.
// Every flag is a key of the case table [wearmap.rough] (cases/wearmap_rough.toml).
// DIR/wearmap_rough.h5 (+ .xdmf sidecar for ParaView), wearmap_rough.csv (per pixel), wearmap_rough_particles.csv
// (per-pixel particle lists), wearmap_rough_curves.csv and PNGs (gnuplot).
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "wearmap_case.hpp"
#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/csv.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/hdf5_file.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/output_set.hpp"
#include "wearscale/core/progress.hpp"
#include "wearscale/core/xdmf.hpp"
#include "wearscale/coupling/plots.hpp"
#include "wearscale/wear/rough_wear_map.hpp"
#include "wearscale/wear/wear_curves.hpp"

namespace wearscale::app {

namespace {

namespace fs = std::filesystem;

// The resolved [wearmap.rough] table.
struct RoughArgs {
  std::size_t n = 512, seeds = 5, n_loads = 20, n_dstar = 20, naive_pixels = 0, naive_max_solves = 0;
  double hurst = 0.8, ql = 8.0, qs = 0.0, nu = 0.3, tensile = 1.0, spot = 0.05, invalid = 0.25;
  std::pair<double, double> loads{0.01, 0.3}, dstar{0.01, 0.2};
  fs::path out;
  bool per_particle = false, naive = false, json = false;
};

// [wearmap.rough] of the case (flags and --set applied), every key range-checked; the resolved values are
// recorded back into `cfg` (defaults included) for the summary and the HDF5 file.
RoughArgs read_rough(Config& cfg, const WearmapCase& c) {
  const std::string k = "wearmap.rough.";
  RoughArgs a;
  naming_flags(c, [&]() {
    const auto count = [&](const char* key, std::size_t fallback, double lo, double hi) {
      return static_cast<std::size_t>(cfg.integer_or(k + key, long(fallback), Range::closed(lo, hi)));
    };
    a.n = count("n", a.n, 16, 4096);
    a.seeds = count("seeds", a.seeds, 1, 1000);
    a.hurst = cfg.number_or(k + "hurst", a.hurst, Range::open_closed(0.0, 1.0));
    a.ql = cfg.number_or(k + "q_l", a.ql, Range::at_least(1.0));
    a.qs = cfg.number_or(k + "q_s", static_cast<double>(a.n) / 8.0, Range::at_least(1.0));
    if (!(a.ql <= a.qs && a.qs <= static_cast<double>(a.n) / 2.0)) {
      const std::string key = k + (cfg.has(k + "q_s") ? "q_s" : "q_l");
      throw cfg.error(key, fmt::format("not allowed with q_l = {}, q_s = {} and n = {}", a.ql, a.qs, a.n),
                      fmt::format("1 ≤ q_l ≤ q_s ≤ n/2 = {} (in 2π/L; q_s defaults to n/8)", a.n / 2));
    }
    a.loads = read_range(cfg, k + "loads", a.loads, Range::open(0.0, 1.0), "p̃_N (5.1)");
    a.n_loads = count("n_loads", a.n_loads, 1, 1000);
    a.dstar = read_range(cfg, k + "dstar_over_l", a.dstar, Range::positive(), "d*/L (4.35)");
    a.n_dstar = count("n_dstar", a.n_dstar, 1, 1000);
    a.nu = cfg.number_or(k + "nu", a.nu, Range::open_closed(-1.0, 0.5));
    a.tensile = cfg.number_or(k + "tensile_strength", a.tensile, Range::positive());
    a.spot = cfg.number_or(k + "spot", a.spot, Range::closed(0.0, 1.0));
    a.invalid = cfg.number_or(k + "invalid_diameter", a.invalid, Range::open_closed(0.0, 1.0));
    a.per_particle =
        cfg.choice_or(k + "energy_balance", "cumulative", {"cumulative", "per_particle"}) == "per_particle";
    a.naive = cfg.choice_or(k + "method", "fast", {"fast", "naive"}) == "naive";
    a.naive_pixels = count("naive_pixels", a.naive_pixels, 0, 1000);
    a.naive_max_solves = static_cast<std::size_t>(cfg.integer_or(k + "naive_max_solves", 0, Range::non_negative()));
    a.out = output_folder(c, cfg, "out/wearmap");
    cfg.reject_unknown_keys();
  });
  a.json = c.json;
  for (const auto& [key, value] :
       {std::pair<const char*, std::string>{"n", fmt::format("{}", a.n)}, {"seeds", fmt::format("{}", a.seeds)},
        {"hurst", toml_number(a.hurst)}, {"q_l", toml_number(a.ql)}, {"q_s", toml_number(a.qs)},
        {"loads", toml_range(a.loads)}, {"n_loads", fmt::format("{}", a.n_loads)},
        {"dstar_over_l", toml_range(a.dstar)}, {"n_dstar", fmt::format("{}", a.n_dstar)}, {"nu", toml_number(a.nu)},
        {"tensile_strength", toml_number(a.tensile)}, {"spot", toml_number(a.spot)},
        {"invalid_diameter", toml_number(a.invalid)},
        {"energy_balance", a.per_particle ? "\"per_particle\"" : "\"cumulative\""},
        {"method", a.naive ? "\"naive\"" : "\"fast\""}, {"naive_pixels", fmt::format("{}", a.naive_pixels)},
        {"naive_max_solves", fmt::format("{}", a.naive_max_solves)}})
    record(cfg, k + key, value);
  return a;
}

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

// Viridis (perceptually uniform, readable in grey and by the colour-blind),
// for the maps; Okabe & Ito's palette for the curves.
const char* const kViridis = "set palette defined (0 '#440154', 1 '#482878', 2 '#3E4989', 3 '#31688E', 4 '#26828E', "
                             "5 '#1F9E89', 6 '#35B779', 7 '#6DCD59', 8 '#B4DE2C', 9 '#FDE725')\n";
const char* const kOkabeIto[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000"};

// Fig. 5.6: one map (column `col` of the pixel CSV) over (p̃_N, d*/L), invalid pixels crossed.
std::string map_script(const fs::path& csv, int col, const std::string& title, bool log_scale,
                       const std::vector<double>& loads, const std::vector<double>& dstars) {
  const std::size_t nl = loads.size(), nd = dstars.size();
  const double ps = 60.0 / static_cast<double>(std::max(nl, nd));
  const double dx = nl > 1 ? 0.5 * (loads.back() - loads.front()) / double(nl - 1) : 0.5 * loads.front();
  const double fy = nd > 1 ? std::pow(dstars.back() / dstars.front(), 0.5 / double(nd - 1)) : 1.5;
  // One header line, then a row per pixel (skip 1).
  return fmt::format(
      "set datafile separator ','\nset title '{}' noenhanced\nset xlabel 'normalized load p̃_N (5.1)' noenhanced\n"
      "set ylabel 'd*/L (4.35), crossed: invalid' noenhanced\nset logscale y\nset xrange [{}:{}]\n"
      "set yrange [{}:{}]\n{}{}set key off\n"
      "plot '{}' skip 1 using 1:2:({}) with points pt 5 ps {:.3g} lc palette, \\\n"
      "  '' skip 1 using 1:($9 > 0.5 ? NaN : $2) with points pt 2 ps {:.3g} lc rgb 'black'\n",
      title, loads.front() - dx, loads.back() + dx, dstars.front() / fy, dstars.back() * fy,
      log_scale ? "set logscale cb\nset format cb '10^{%L}'\n" : "", kViridis, csv.string(),
      log_scale ? fmt::format("${} > 0 ? ${} : NaN", col, col) : fmt::format("${}", col), ps, 0.6 * ps);
}

// Fig. 5.7: curves against p̃_N at every `step`-th d*, mean ± sd, invalid
// points cut; the number of particles also smoothed (dashed, §5.2; a count,
// drawn from 0 up: the filter's undershoot below 0 is not drawn).
std::string curves_script(const fs::path& csv, const std::vector<double>& dstars, bool volume) {
  const std::size_t nd = dstars.size(), step = std::max<std::size_t>(1, nd / 5);
  const int off = volume ? 4 : 2;  // columns per d*: count, sd, volume, sd, valid, smoothed count
  std::string plots;
  for (std::size_t d = 0, c = 0; d < nd; d += step, ++c) {
    const int base = static_cast<int>(6 * d);
    const char* colour = kOkabeIto[c % (sizeof kOkabeIto / sizeof *kOkabeIto)];
    plots += fmt::format("{}'{}' skip 1 using 1:(column({}) > 0.5 ? column({}) : NaN):(column({})) with yerrorlines "
                         "lw 1.5 pt 7 ps 0.8 lc rgb '{}' title 'd*/L = {:.3g}'",
                         plots.empty() ? "" : ", ", csv.string(), 6 + base, off + base, off + 1 + base, colour,
                         dstars[d]);
    if (!volume)
      plots += fmt::format(", '' skip 1 using 1:(column({}) > 0.5 ? max(0, column({})) : NaN) with lines dt 2 lw 1.5 "
                           "lc rgb '{}' notitle",
                           6 + base, 7 + base, colour);
  }
  return fmt::format(
      "set datafile separator ','\nmax(a, b) = a > b ? a : b\nset title '{}'\n"
      "set xlabel 'normalized load p̃_N (5.1)' noenhanced\nset ylabel '{}'\n{}set grid\n"
      "set offsets graph 0.03, graph 0.03, 0, 0\nset key top left noenhanced\nplot {}\n",
      volume ? "Wear volume (Fig. 5.7b)" : "Number of particles (Fig. 5.7a; dashed: Savitzky-Golay, 3/11)",
      volume ? "wear volume V / L^3" : "number of particles", volume ? "set logscale y\nset format y '10^{%L}'\n" : "set yrange [0:*]\n",
      plots);
}

nlohmann::json result(double value, const char* unit, const std::string& description) {
  return {{"value", value}, {"unit", unit}, {"description", description}};
}

int run_rough(const WearmapCase& wcase) {
  Config cfg = build_case(wcase);
  const RoughArgs a = read_rough(cfg, wcase);
  wear::RoughWearMapSpec spec;
  spec.surface.n = a.n;
  spec.surface.hurst = a.hurst;
  spec.surface.k_l = a.ql;
  spec.surface.k_s = a.qs;
  spec.surface.poisson = a.nu;
  spec.seeds.clear();
  for (std::size_t s = 1; s <= a.seeds; ++s) spec.seeds.push_back(s);
  spec.loads = linear(a.loads, a.n_loads);
  spec.critical_diameters = geometric(a.dstar, a.n_dstar);
  spec.tensile_strength = a.tensile;
  spec.spot = a.spot;
  spec.invalid_diameter = a.invalid;
  spec.options.cumulative = !a.per_particle;
  spec.options.method = a.naive ? wear::EnergyReleaseMethod::Naive : wear::EnergyReleaseMethod::Fast;
  wear::validate(spec);
  const fs::path& out = a.out;
  const OutputLock lock = lock_output_folder(wcase, out);  // before the work: a second writer is refused now

  const std::size_t nl = spec.loads.size(), nd = spec.critical_diameters.size();
  Progress bar("wearmap rough", static_cast<double>(spec.seeds.size() * nl), "contacts");
  const auto t0 = std::chrono::steady_clock::now();
  const auto map = wear::rough_wear_map(spec, [&](std::size_t done, std::size_t) { bar.update(double(done)); });
  bar.finish();
  const double total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // The naive baseline on a few pixels (first seed, loads spread over the axis, middle d*), against the fast
  // model on the same pixels. The naive run stops after --naive-max-solves solves; its time per pixel is then
  // extrapolated as (time per solve) × (the solves it needs: every candidate the fast run evaluated or bounded,
  // i.e. examined and not blocked by a recorded particle, plus one update per particle).
  nlohmann::json baseline;
  if (a.naive_pixels > 0) {
    wear::RoughContactSeries series(spec.surface, spec.seeds.front());
    const double nu = spec.surface.poisson;
    wear::ShearedJunctions j{1.0, 1.0 / (2.0 * (1.0 + nu)), nu, spec.tensile_strength, spec.spot};
    const double dstar = spec.critical_diameters[nd / 2];
    double setup_s = 0.0, fast_s = 0.0, naive_s = 0.0, naive_est = 0.0;
    std::size_t naive_solves = 0, examined = 0, pixels = 0, truncated = 0;
    bool same = true;
    const std::size_t k = std::min(a.naive_pixels, nl);
    for (std::size_t i = 0; i < k; ++i) {
      const std::size_t l = k == 1 ? nl / 2 : i * (nl - 1) / (k - 1);
      const auto cmap = series.at_load(spec.loads[l]);
      const auto s0 = std::chrono::steady_clock::now();
      const wear::DetachmentModel model(cmap, j);
      const auto t1 = std::chrono::steady_clock::now();
      wear::DetachmentOptions fast = spec.options, slow = spec.options;
      fast.method = wear::EnergyReleaseMethod::Fast;
      slow.method = wear::EnergyReleaseMethod::Naive;
      slow.max_solves = a.naive_max_solves;
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
    baseline = {{"pixels", pixels},
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

  // Outputs: built under partial names, committed together at the end.
  OutputSet outputs(out, "wearmap_rough_summary.json");
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
  write_csv(csv, names, columns, plain(names), {"wearscale wearmap rough: mean and sample sd over seeds; valid = 0 where the mean "
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
  nlohmann::json files = {h5.string(), xmf.string(), csv.string(), pcsv.string(), ccsv.string(), kcsv.string()};
  // Fig. 5.6 maps and Fig. 5.7 curves (column 3: count, 5: volume).
  const std::pair<std::string, std::string> plots[] = {
      {map_script(OutputSet::readable(csv), 3, "Number of particles (Fig. 5.6a)", false, spec.loads,
                  spec.critical_diameters),
       "count"},
      {map_script(OutputSet::readable(csv), 5, "Wear volume / L^3 (Fig. 5.6b)", true, spec.loads,
                  spec.critical_diameters),
       "volume"},
      {curves_script(OutputSet::readable(ccsv), spec.critical_diameters, false), "curves_count"},
      {curves_script(OutputSet::readable(ccsv), spec.critical_diameters, true), "curves_volume"}};
  for (const auto& [script, name] : plots)
    if (auto p = coupling::render_plot(script, out / ("wearmap_rough_" + name + ".png"), 1000, 760))
      files.push_back(p->string());

  std::size_t invalid = 0;
  double max_count = 0.0;
  for (const auto& p : map.pixels) {
    invalid += p.valid ? 0 : 1;
    max_count = std::max(max_count, p.count_mean);
  }
  const double pixels = static_cast<double>(nl * nd);
  nlohmann::json results;
  results["pixels"] = result(pixels, "", "map pixels (p̃_N × d*/L)");
  results["invalid_fraction"] = result(double(invalid) / pixels, "", "share of pixels with particles ≥ the invalid size");
  results["max_count"] = result(max_count, "", "largest mean number of particles on the map");
  double max_smoothed = 0.0;
  for (const auto& c : peaks)
    if (c.found) max_smoothed = std::max(max_smoothed, c.count);
  results["max_count_smoothed"] =
      result(max_smoothed, "", "largest maximum of the Fig. 5.7 curves read on their smoothed version (§5.2)");
  results["seconds"] = result(total_seconds, "s", "wall time of the map (all seeds)");
  results["seconds_per_pixel"] =
      result(total_seconds / (pixels * double(spec.seeds.size())), "s", "wall time per pixel and seed");
  results["contact_seconds"] = result(map.contact_seconds, "s", "BEM contact solves");
  results["model_setup_seconds"] = result(map.setup_seconds, "s", "crack stresses, candidates, u of the full loading");
  results["detach_seconds"] = result(map.detach_seconds, "s", "detachment procedure over all pixels and seeds");
  results["candidates"] = result(double(map.candidates), "", "candidate particles summed over seeds and loads");
  results["energy_evaluations"] = result(double(map.energy_evaluations), "", "ΔE_el (5.3) evaluated in full");
  if (!baseline.is_null()) {
    results["naive_ratio"] = result(baseline["ratio"].get<double>(), "",
                                    "naive (one solve per candidate) over fast time per pixel");
    results["naive_seconds_per_pixel"] = result(baseline["naive_seconds_per_pixel"].get<double>(), "s",
                                                "naive baseline (extrapolated on truncated pixels)");
    results["fast_seconds_per_pixel"] = result(baseline["fast_seconds_per_pixel"].get<double>(), "s",
                                               "fast, same pixels (the shared set-up apart)");
    results["setup_seconds_per_pixel"] = result(baseline["setup_seconds_per_pixel"].get<double>(), "s",
                                                "candidates, crack stresses and u of the full loading, shared by both");
  }
  // parameters: the resolved case (every key of [wearmap.rough], defaults included); axes: the sample points.
  nlohmann::json summary = {{"kind", "rough"},
                            {"results", results},
                            {"parameters", cfg.to_json()},
                            {"axes", {{"p_N_tilde", spec.loads}, {"dstar_over_L", spec.critical_diameters}}},
                            {"files", files},
                            {"output_dir", out.string()}};
  if (!baseline.is_null()) summary["baseline"] = baseline;
  outputs.commit(summary);
  if (a.json) {
    std::cout << summary.dump(2) << '\n';
    return 0;
  }
  print_results(results);
  for (const auto& f : files) log::info("wrote {}", f.get<std::string>());
  return 0;
}

}  // namespace

Command add_wearmap_rough(CLI::App& wearmap) {
  auto c = std::make_shared<WearmapCase>();
  auto* cmd = wearmap.add_subcommand("rough", "Numerical wear maps of rough contacts (ch. 5, Fig. 5.6–5.7): number of "
                                              "particles and wear volume over (p̃_N, d*/L), averaged over surfaces");
  const std::string k = "wearmap.rough.";
  add_case_options(cmd, *c, "wearmap.rough");
  add_case_flag(cmd, *c, "--n", k + "n", "Grid points per side, 16 to 4096 (§5.3: 512)");
  add_case_flag(cmd, *c, "--seeds", k + "seeds", "Random surfaces to average, seeds 1…S, S ≤ 1000 (default 5)");
  add_case_flag(cmd, *c, "--hurst", k + "hurst", "Hurst exponent H (default 0.8)");
  add_case_flag(cmd, *c, "--ql", k + "q_l", "q_l in units of 2π/L (= q_r) (default 8)");
  add_case_flag(cmd, *c, "--qs", k + "q_s", "q_s in units of 2π/L (default n/8)");
  add_case_range_flag(cmd, *c, "--loads", k + "loads", "Normalized loads p̃_N (5.1), evenly spaced (default 0.01:0.3)");
  add_case_flag(cmd, *c, "--n-loads", k + "n_loads", "Points along p̃_N (default 20)");
  add_case_range_flag(cmd, *c, "--dstar-over-l", k + "dstar_over_l",
                      "Critical diameters d*/L (4.35), geometric (default 0.01:0.2)");
  add_case_flag(cmd, *c, "--n-dstar", k + "n_dstar", "Points along d*/L (default 20)");
  add_case_flag(cmd, *c, "--nu", k + "nu", "Poisson's ratio ν (default 0.3)");
  add_case_flag(cmd, *c, "--tensile-strength", k + "tensile_strength",
                "σ_m/σ_j of the crack criterion (4.25) (default 1)");
  add_case_flag(cmd, *c, "--spot", k + "spot", "Crack sites within this fraction of each micro-contact's peak edge "
                                               "stress (1: every edge past σ_m) (default 0.05)");
  add_case_flag(cmd, *c, "--invalid-diameter", k + "invalid_diameter",
                "Pixels whose mean largest particle is ≥ this × L are invalid (default 0.25)");
  add_case_switch(cmd, *c, "--per-particle", k + "energy_balance", "\"per_particle\"",
                  "Each particle pays for itself (default: cumulative balance)");
  add_case_switch(cmd, *c, "--naive", k + "method", "\"naive\"",
                  "Energy release by one full solve per candidate (the slow baseline)");
  add_case_flag(cmd, *c, "--naive-pixels", k + "naive_pixels", "Also time the naive baseline against the fast model "
                                                                "on K pixels of the first seed (middle d*)");
  add_case_flag(cmd, *c, "--naive-max-solves", k + "naive_max_solves",
                "Stop each naive pixel after this many solves and extrapolate its time (0: run it through)");
  return [c]() { return run_rough(*c); };
}

}  // namespace wearscale::app
