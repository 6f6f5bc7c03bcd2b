// wearscale wearmap analytic2d [CASE.toml] [--dr-over-dstar MIN:MAX] [--da-over-dstar MIN:MAX] [--n N]
//                              [--set KEY=VALUE]... [--out DIR] [--json]
// wearscale wearmap analytic3d [CASE.toml] [--d-over-l MIN:MAX] [--dstar-over-l MIN:MAX] [--n N]
//                              [--interaction max|min | --nu NU --theta RAD] [--set KEY=VALUE]... [--out DIR] [--json]
// The analytic wear maps of thesis ch. 3 (Fig. 3.7) and ch. 4 (Fig. 4.6):
// DIR/wearmap_<kind>.h5 (+ .xdmf sidecar for ParaView), .csv, .png (gnuplot,
// with the analytic lines) and _summary.json. Every flag is a key of the case
// table [wearmap.analytic2d] / [wearmap.analytic3d] (see wearmap_case.hpp).
#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "wearmap_case.hpp"
#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/output_set.hpp"
#include "wearscale/coupling/palette.hpp"
#include "wearscale/coupling/plots.hpp"
#include "wearscale/wear/analytic_wear_maps.hpp"
#include "wearscale/wear/two_contacts_3d.hpp"
#include "wearscale/wear/wear_map_io.hpp"

namespace wearscale::app {

namespace {

namespace fs = std::filesystem;
constexpr double pi = std::numbers::pi;

// `axis` with the range of the case key `key` (when set) and `n` points.
wear::MapAxis read_axis(const Config& t, const std::string& key, wear::MapAxis axis, std::size_t n,
                        const Range& element) {
  const auto [min, max] = read_range(t, key, {axis.min, axis.max}, element, axis.label);
  axis.min = min, axis.max = max, axis.n = n;
  return axis;
}

// ------------------------------------------------------------------ plot ---

// "one_separated" → "one separated" (gnuplot's enhanced text reads _ as a subscript).
std::string spaced(std::string name) {
  for (auto& ch : name)
    if (ch == '_') ch = ' ';
  return name;
}

// The region codes as a heat map, with palette entries named after the regions.
std::string heat_map(const wear::WearMap& map, const std::string& title, const fs::path& csv,
                     const std::vector<std::string>& colours) {
  std::string tics;
  for (const auto& [code, name] : map.region_names)
    tics += fmt::format("{}'{}' {}", tics.empty() ? "" : ", ", spaced(name), code);
  std::string palette;
  for (std::size_t k = 0; k < colours.size(); ++k)
    palette += fmt::format("{}{} '{}'", k ? ", " : "", map.region_names[k].first, colours[k]);
  const int lo = map.region_names.front().first, hi = map.region_names.back().first;
  return fmt::format(
      "set datafile separator ','\nset title \"{}\"\nset xlabel '{}'\nset ylabel '{}'\nset rmargin 17\n"
      "set xrange [{}:{}]\nset yrange [{}:{}]\nset palette defined ({})\nset palette maxcolors {}\n"
      "set cbrange [{}:{}]\nset cbtics ({})\nset key top left box opaque\nset samples 1000\n"
      "plot '{}' skip 1 using 1:2:3 with image notitle",
      title, map.x.label, map.y.label, map.x.min, map.x.max, map.y.min, map.y.max, palette, colours.size(), lo - 0.5,
      hi + 0.5, tics, csv.string());
}

namespace oi = coupling::okabe_ito;
// The regions' fills: neutral greys for the inaccessible (d_a < d_r) and plastic
// regions, Okabe-Ito categories tinted halfway to white for the wear regions,
// so that the analytic lines, drawn in the full colours, show over them.
constexpr double kFill = 0.5;

std::optional<fs::path> plot_2d(const wear::WearMap& map, const fs::path& csv, const fs::path& png) {
  // Fig. 3.7: d_r = d* (3.25) and d_a = d_r²/d* (3.27) where d_a ≥ d_r, and d_a = d_r (a single contact).
  const std::string script =
      heat_map(map, "2D wear map of N micro-contacts (thesis Fig. 3.7)", csv,
               {"#BBBBBB", "#F7F7F7", oi::tint(oi::sky_blue, kFill), oi::tint(oi::orange, kFill)}) +
      fmt::format(", \\\n  '+' using (1):(1 + $0/999*({} - 1)) with lines lw 2 dt 2 lc rgb 'black' "
                  "title 'd_r = d* (3.25)'",
                  map.y.max) +
      fmt::format(", \\\n  (x >= 1 ? x*x : 1/0) with lines lw 2 dt 2 lc rgb '{}' title 'd_a = d_r^2/d* (3.27)', \\\n",
                  oi::blue) +
      "  x with lines lw 1 lc rgb 'black' title 'd_a = d_r (one contact)'\n";
  return coupling::render_plot(script, png, 1000, 760);
}

std::optional<fs::path> plot_3d(const wear::WearMap& map, double c_inter, const fs::path& csv, const fs::path& png) {
  // Fig. 4.6: the lines R = 1 of (4.48) at this C_inter (solid) and at the other bound (dashed), and d = d*.
  const double other = c_inter > 0.5 ? wear::min_interaction_constant : wear::max_interaction_constant;
  std::string lines;
  // Each case's line in the full colour of the region it bounds.
  const char* colours[] = {oi::blue, oi::bluish_green, oi::vermillion};
  for (const double c : {c_inter, other})
    for (std::size_t k = 0; k < wear::particle_cases.size(); ++k) {
      const auto d = wear::particle_cases[k];
      const std::string c_case = d == wear::ParticleCase::OneSeparated   ? "1"
                                 : d == wear::ParticleCase::TwoSeparated ? "0.5"
                                                                         : "(x/(1+x))**2";
      lines += fmt::format(", \\\n  ({:g} + 3*pi/8*{:.17g}*x)*x*{} with lines lw 2 dt {} lc rgb '{}' "
                           "title '{}, C_{{inter}} = {:.3g}'",
                           wear::count_constant(d), c, c_case, c == c_inter ? 1 : 2, colours[k], spaced(wear::name(d)), c);
    }
  const std::string title =
      fmt::format("3D wear map of two micro-contacts, R ≥ 1 (4.48) at C_{{inter}} = {:.4g} (thesis Fig. 4.6)", c_inter);
  const std::string script = heat_map(map, title, csv,
                                        {"#F7F7F7", oi::tint(oi::sky_blue, kFill), oi::tint(oi::bluish_green, kFill),
                                         oi::tint(oi::orange, kFill)}) + lines +
                             ", \\\n  x with lines lw 1 dt 3 lc rgb 'black' title 'd = d*'\n";
  return coupling::render_plot(script, png, 1000, 760);
}

// --------------------------------------------------------------- running ---

nlohmann::json result(double value, const char* unit, const std::string& description) {
  return {{"value", value}, {"unit", unit}, {"description", description}};
}

// Writes the map (HDF5 with its XDMF sidecar, CSV, PNG) and the summary into the output folder.
int finish(const WearmapCase& c, Config& cfg, const fs::path& out, const wear::WearMap& map, nlohmann::json results,
           const std::function<std::optional<fs::path>(const fs::path&, const fs::path&)>& plot) {
  const std::string stem = fmt::format("wearmap_{}", map.kind);
  OutputSet outputs(out, stem + "_summary.json");  // published together, the summary last
  const fs::path h5 = out / (stem + ".h5"), csv = out / (stem + ".csv"),
                 png = out / (stem + ".png");
  const fs::path xmf = wear::write_wear_map_h5(h5, map, cfg.to_toml());
  wear::write_wear_map_csv(csv, map);
  nlohmann::json files = {h5.string(), xmf.string(), csv.string()};
  if (const auto p = plot(OutputSet::readable(csv), png)) files.push_back(p->string());

  const double total = static_cast<double>(map.region.size());
  for (const auto& [code, name] : map.region_names)
    results["fraction_" + name] = result(static_cast<double>(map.count(code)) / total, "",
                                         fmt::format("share of the map in region {} ({})", code, name));
  const nlohmann::json summary = {{"kind", map.kind}, {"results", results}, {"parameters", cfg.to_json()},
                                  {"files", files}, {"output_dir", out.string()}};
  outputs.commit(summary);
  if (c.json) {
    std::cout << summary.dump(2) << '\n';
    return 0;
  }
  print_results(results);
  for (const auto& f : files) log::info("wrote {}", f.get<std::string>());
  return 0;
}

// Fig. 3.7 over [wearmap.analytic2d]: dr_over_dstar, da_over_dstar = [MIN, MAX], n.
int run_analytic2d(const WearmapCase& c) {
  Config cfg = build_case(c);
  const std::string k = "wearmap.analytic2d.";
  const auto [x, y, out] = naming_flags(c, [&]() {
    const long points = long(wear::default_real_size_axis().n);
    const auto n = static_cast<std::size_t>(cfg.integer_or(k + "n", points, Range::closed(2, 4096)));
    auto dr = read_axis(cfg, k + "dr_over_dstar", wear::default_real_size_axis(), n, Range::non_negative());
    auto da = read_axis(cfg, k + "da_over_dstar", wear::default_apparent_size_axis(), n, Range::non_negative());
    fs::path folder = output_folder(c, cfg, "out/wearmap");
    cfg.reject_unknown_keys();
    return std::tuple{dr, da, folder};
  });
  record(cfg, k + "n", fmt::format("{}", x.n));
  record(cfg, k + "dr_over_dstar", toml_range({x.min, x.max}));
  record(cfg, k + "da_over_dstar", toml_range({y.min, y.max}));
  const OutputLock lock = lock_output_folder(c, out);
  const auto map = wear::analytic_map_2d(x, y);
  return finish(c, cfg, out, map, nlohmann::json::object(),
                [&](const fs::path& csv, const fs::path& png) { return plot_2d(map, csv, png); });
}

// Fig. 4.6 over [wearmap.analytic3d]: d_over_l, dstar_over_l = [MIN, MAX], n, and interaction = "max" | "min"
// or nu, theta.
int run_analytic3d(const WearmapCase& c) {
  Config cfg = build_case(c);
  const std::string k = "wearmap.analytic3d.";
  const auto [x, y, nu, theta, out] = naming_flags(c, [&]() {
    const long points = long(wear::default_d_over_l_axis().n);
    const auto n = static_cast<std::size_t>(cfg.integer_or(k + "n", points, Range::closed(2, 4096)));
    auto d = read_axis(cfg, k + "d_over_l", wear::default_d_over_l_axis(), n, Range::closed(0.0, 1.0));
    auto dstar = read_axis(cfg, k + "dstar_over_l", wear::default_dstar_over_l_axis(), n, Range::non_negative());
    double poisson = cfg.number_or(k + "nu", 0.5, Range::open_closed(-1.0, 0.5));
    double angle = cfg.number_or(k + "theta", 0.0, Range::any());
    cfg.mark_used(k + "interaction");
    if (cfg.has(k + "interaction")) {  // Fig. 4.6: ν = ½ with θ = 0 (most) or π/2 (least)
      const std::string i = cfg.choice(k + "interaction", {"max", "min"});
      for (const char* fixed : {"nu", "theta"})
        if (cfg.has(k + fixed))
          throw cfg.error(k + fixed, "cannot be set together with interaction (which fixes ν = 0.5 and θ)",
                          "either interaction, or nu and theta");
      poisson = 0.5;
      angle = i == "max" ? 0.0 : pi / 2;
    }
    fs::path folder = output_folder(c, cfg, "out/wearmap");
    cfg.reject_unknown_keys();
    return std::tuple{d, dstar, poisson, angle, folder};
  });
  record(cfg, k + "n", fmt::format("{}", x.n));
  record(cfg, k + "d_over_l", toml_range({x.min, x.max}));
  record(cfg, k + "dstar_over_l", toml_range({y.min, y.max}));
  if (!cfg.has(k + "interaction")) {
    record(cfg, k + "nu", toml_number(nu));
    record(cfg, k + "theta", toml_number(theta));
  }
  const double ci = wear::interaction_constant(nu, theta);
  const OutputLock lock = lock_output_folder(c, out);
  const auto map = wear::analytic_map_3d(x, y, ci);
  nlohmann::json results;
  results["C_inter"] = result(ci, "", "interaction constant (1 − ν sin²θ)/(2 − ν) (4.49)");
  // Adjacent contacts (d = l): the smallest d/d* of each case, 1/boundary(1).
  for (const auto d : wear::particle_cases)
    results[fmt::format("least_d_{}", wear::name(d))] =
        result(1.0 / wear::boundary_dstar_over_l(d, 1.0, ci), "",
               fmt::format("least d/d* of two adjacent contacts (d = l) for {} (4.48)", wear::name(d)));
  return finish(c, cfg, out, map, results,
                [&](const fs::path& csv, const fs::path& png) { return plot_3d(map, ci, csv, png); });
}

}  // namespace

Command add_wearmap(CLI::App& app) {
  auto* cmd = app.add_subcommand("wearmap", "Wear maps of sheared micro-contacts (thesis ch. 3–5): which particles "
                                            "can detach, as regions of an energy ratio R ≥ 1");
  cmd->require_subcommand(1);
  auto commands = std::make_shared<std::map<CLI::App*, Command>>();
  auto add = [&](Command command) { (*commands)[cmd->get_subcommands({}).back()] = std::move(command); };

  auto a2 = std::make_shared<WearmapCase>();
  auto* two = cmd->add_subcommand("analytic2d", "2D map of N micro-contacts (Fig. 3.7): plastic, separated "
                                                "(d_r ≥ d*, 3.25), combined (d_a ≤ d_r²/d*, 3.27)");
  add_case_options(two, *a2, "wearmap.analytic2d");
  add_case_range_flag(two, *a2, "--dr-over-dstar", "wearmap.analytic2d.dr_over_dstar",
                      "Range of the real contact size d_r/d* (default 0:3)");
  add_case_range_flag(two, *a2, "--da-over-dstar", "wearmap.analytic2d.da_over_dstar",
                      "Range of the apparent contact size d_a/d* (default 0:6)");
  add_case_flag(two, *a2, "--n", "wearmap.analytic2d.n", "Points along each axis, 2 to 4096 (default 301)");
  add([a2]() { return run_analytic2d(*a2); });

  auto a3 = std::make_shared<WearmapCase>();
  auto* three = cmd->add_subcommand("analytic3d", "3D map of two circular micro-contacts (Fig. 4.6): plastic, one "
                                                  "separated, two separated, combined, from R of (4.48)");
  add_case_options(three, *a3, "wearmap.analytic3d");
  add_case_range_flag(three, *a3, "--d-over-l", "wearmap.analytic3d.d_over_l",
                      "Range of d/l, contact diameter over centre distance, within 0:1 (default 0:1)");
  add_case_range_flag(three, *a3, "--dstar-over-l", "wearmap.analytic3d.dstar_over_l", "Range of d*/l (default 0:2)");
  auto* interaction = add_case_flag(three, *a3, "--interaction", "wearmap.analytic3d.interaction",
                                    "max (ν = 0.5, θ = 0: C_inter = 2/3) or min (ν = 0.5, θ = π/2: 1/3) (Fig. 4.6)")
                          ->check(CLI::IsMember({"max", "min"}));
  auto* nu = add_case_flag(three, *a3, "--nu", "wearmap.analytic3d.nu", "Poisson's ratio ν in (−1, 0.5] (default 0.5)");
  auto* theta = add_case_flag(three, *a3, "--theta", "wearmap.analytic3d.theta",
                              "Angle θ between the load and the line of the centres [rad] (default 0)");
  interaction->excludes(nu)->excludes(theta);
  add_case_flag(three, *a3, "--n", "wearmap.analytic3d.n", "Points along each axis, 2 to 4096 (default 201)");
  add([a3]() { return run_analytic3d(*a3); });

  add(add_wearmap_rough(*cmd));  // the numerical map of ch. 5

  return [cmd, commands]() {
    for (auto* sub : cmd->get_subcommands())
      if (commands->count(sub) != 0) return commands->at(sub)();
    return exit_bad_input;
  };
}

}  // namespace wearscale::app
