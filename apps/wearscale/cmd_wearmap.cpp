// wearscale wearmap analytic2d [--dr-over-dstar MIN:MAX] [--da-over-dstar MIN:MAX] [--n N] [--out DIR] [--json]
// wearscale wearmap analytic3d [--d-over-l MIN:MAX] [--dstar-over-l MIN:MAX] [--n N]
//                              [--interaction max|min | --nu NU --theta RAD] [--out DIR] [--json]
// The analytic wear maps of thesis ch. 3 (Fig. 3.7) and ch. 4 (Fig. 4.6):
// DIR/wearmap_<kind>.h5, .csv and .png (gnuplot, with the analytic lines).
#include <charconv>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/coupling/plots.hpp"
#include "wearscale/wear/analytic_wear_maps.hpp"
#include "wearscale/wear/two_contacts_3d.hpp"
#include "wearscale/wear/wear_map_io.hpp"

namespace wearscale::app {

namespace {

namespace fs = std::filesystem;
constexpr double pi = std::numbers::pi;

struct MapArgs {
  std::string x_range, y_range, out = "out/wearmap", interaction;
  std::size_t n = 0;
  double nu = 0.5, theta = 0.0;
  CLI::Option *nu_opt = nullptr, *theta_opt = nullptr;
  bool json = false;
};

double parse_number(const std::string& flag, const std::string& text, const std::string& whole,
                    const std::string& allowed) {
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v))
    throw InputError(fmt::format("{} = '{}' is not a range; allowed: MIN:MAX with {}", flag, whole, allowed));
  return v;
}

/// "MIN:MAX" into `axis` (with `n` points if given); InputError naming the flag
/// unless lo ≤ MIN < MAX ≤ hi.
void parse_range(wear::MapAxis& axis, const std::string& flag, const std::string& text, std::size_t n, double lo,
                 double hi) {
  const std::string allowed = std::isfinite(hi) ? fmt::format("{:g} ≤ MIN < MAX ≤ {:g}", lo, hi)
                                                : fmt::format("{:g} ≤ MIN < MAX", lo);
  if (n != 0) axis.n = n;
  if (text.empty()) return;
  const auto colon = text.find(':');
  if (colon == std::string::npos)
    throw InputError(fmt::format("{} = '{}' is not a range; allowed: MIN:MAX with {}", flag, text, allowed));
  const double min = parse_number(flag, text.substr(0, colon), text, allowed);
  const double max = parse_number(flag, text.substr(colon + 1), text, allowed);
  if (!(min >= lo && max <= hi && min < max))
    throw InputError(fmt::format("{} = '{}' is not allowed; allowed: {} ({})", flag, text, allowed, axis.label));
  axis.min = min;
  axis.max = max;
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

std::optional<fs::path> plot_2d(const wear::WearMap& map, const fs::path& csv, const fs::path& png) {
  // Fig. 3.7: d_r = d* (3.25) and d_a = d_r²/d* (3.27) where d_a ≥ d_r, and d_a = d_r (a single contact).
  const std::string script =
      heat_map(map, "2D wear map of N micro-contacts (thesis Fig. 3.7)", csv, {"#bdbdbd", "#f7f7f7", "#9ecae1", "#de2d26"}) +
      fmt::format(", \\\n  '+' using (1):(1 + $0/999*({} - 1)) with lines lw 2 dt 2 lc rgb 'black' "
                  "title 'd_r = d* (3.25)'",
                  map.y.max) +
      ", \\\n  (x >= 1 ? x*x : 1/0) with lines lw 2 dt 2 lc rgb '#08519c' title 'd_a = d_r^2/d* (3.27)', \\\n"
      "  x with lines lw 1 lc rgb 'black' title 'd_a = d_r (one contact)'\n";
  return coupling::render_plot(script, png, 1000, 760);
}

std::optional<fs::path> plot_3d(const wear::WearMap& map, double c_inter, const fs::path& csv, const fs::path& png) {
  // Fig. 4.6: the lines R = 1 of (4.48) at this C_inter (solid) and at the other bound (dashed), and d = d*.
  const double other = c_inter > 0.5 ? wear::min_interaction_constant : wear::max_interaction_constant;
  std::string lines;
  const char* colours[] = {"#08519c", "#006d2c", "#a50f15"};
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
  const std::string script = heat_map(map, title, csv, {"#f7f7f7", "#c6dbef", "#a1d99b", "#fcae91"}) + lines +
                             ", \\\n  x with lines lw 1 dt 3 lc rgb 'black' title 'd = d*'\n";
  return coupling::render_plot(script, png, 1000, 760);
}

// --------------------------------------------------------------- running ---

nlohmann::json result(double value, const char* unit, const std::string& description) {
  return {{"value", value}, {"unit", unit}, {"description", description}};
}

int finish(const MapArgs& a, const wear::WearMap& map, nlohmann::json results, nlohmann::json parameters,
           const std::function<std::optional<fs::path>(const fs::path&, const fs::path&)>& plot) {
  const fs::path out(a.out);
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec || !fs::is_directory(out))
    throw InputError(fmt::format("--out = '{}' cannot be used as an output folder ({}); allowed: a folder that can be "
                                 "created or written", a.out, ec ? ec.message() : "not a folder"));
  const fs::path h5 = out / fmt::format("wearmap_{}.h5", map.kind), csv = out / fmt::format("wearmap_{}.csv", map.kind),
                 png = out / fmt::format("wearmap_{}.png", map.kind);
  wear::write_wear_map_h5(h5, map);
  wear::write_wear_map_csv(csv, map);
  nlohmann::json files = {h5.string(), csv.string()};
  if (const auto p = plot(csv, png)) files.push_back(p->string());

  const double total = static_cast<double>(map.region.size());
  for (const auto& [code, name] : map.region_names)
    results["fraction_" + name] = result(static_cast<double>(map.count(code)) / total, "",
                                         fmt::format("share of the map in region {} ({})", code, name));
  parameters[map.x.name] = {{"min", map.x.min}, {"max", map.x.max}, {"n", map.x.n}};
  parameters[map.y.name] = {{"min", map.y.min}, {"max", map.y.max}, {"n", map.y.n}};
  if (a.json) {
    std::cout << nlohmann::json{{"kind", map.kind}, {"results", results}, {"parameters", parameters}, {"files", files},
                                {"output_dir", out.string()}}
                     .dump(2)
              << '\n';
    return 0;
  }
  print_results(results);
  for (const auto& f : files) log::info("wrote {}", f.get<std::string>());
  return 0;
}

int run_analytic2d(const MapArgs& a) {
  auto x = wear::default_real_size_axis(), y = wear::default_apparent_size_axis();
  const double inf = std::numeric_limits<double>::infinity();
  parse_range(x, "--dr-over-dstar", a.x_range, a.n, 0.0, inf);
  parse_range(y, "--da-over-dstar", a.y_range, a.n, 0.0, inf);
  const auto map = wear::analytic_map_2d(x, y);
  return finish(a, map, nlohmann::json::object(), nlohmann::json::object(),
                [&](const fs::path& csv, const fs::path& png) { return plot_2d(map, csv, png); });
}

int run_analytic3d(const MapArgs& a) {
  auto x = wear::default_d_over_l_axis(), y = wear::default_dstar_over_l_axis();
  parse_range(x, "--d-over-l", a.x_range, a.n, 0.0, 1.0);
  parse_range(y, "--dstar-over-l", a.y_range, a.n, 0.0, std::numeric_limits<double>::infinity());
  double nu = a.nu, theta = a.theta;
  if (!a.interaction.empty()) {  // Fig. 4.6: ν = ½ with θ = 0 (most) or π/2 (least)
    nu = 0.5;
    theta = a.interaction == "max" ? 0.0 : pi / 2;
  }
  if (!(nu > -1.0 && nu <= 0.5) || !std::isfinite(nu))
    throw InputError(fmt::format("--nu = {} is not allowed; allowed: −1 < ν ≤ 0.5", nu));
  if (!std::isfinite(theta))
    throw InputError(fmt::format("--theta = {} is not allowed; allowed: a finite angle in radians", theta));
  const double c = wear::interaction_constant(nu, theta);
  const auto map = wear::analytic_map_3d(x, y, c);
  nlohmann::json results;
  results["C_inter"] = result(c, "", "interaction constant (1 − ν sin²θ)/(2 − ν) (4.49)");
  // Adjacent contacts (d = l): the smallest d/d* of each case, 1/boundary(1).
  for (const auto d : wear::particle_cases)
    results[fmt::format("least_d_{}", wear::name(d))] =
        result(1.0 / wear::boundary_dstar_over_l(d, 1.0, c), "",
               fmt::format("least d/d* of two adjacent contacts (d = l) for {} (4.48)", wear::name(d)));
  const nlohmann::json parameters = {{"nu", nu}, {"theta", theta}};
  return finish(a, map, results, parameters,
                [&](const fs::path& csv, const fs::path& png) { return plot_3d(map, c, csv, png); });
}

void common(CLI::App* cmd, MapArgs& a, std::size_t default_n) {
  cmd->add_option("--n", a.n, fmt::format("Points along each axis (default {})", default_n))->check(CLI::Range(2, 4096));
  cmd->add_option("--out", a.out, "Output folder")->capture_default_str();
  cmd->add_flag("--json", a.json, "Print one JSON object with the results, parameters and files");
}

}  // namespace

Command add_wearmap(CLI::App& app) {
  auto* cmd = app.add_subcommand("wearmap", "Wear maps of sheared micro-contacts (thesis ch. 3–5): which particles "
                                            "can detach, as regions of an energy ratio R ≥ 1");
  cmd->require_subcommand(1);
  auto commands = std::make_shared<std::map<CLI::App*, Command>>();
  auto add = [&](Command command) { (*commands)[cmd->get_subcommands({}).back()] = std::move(command); };

  auto a2 = std::make_shared<MapArgs>();
  auto* two = cmd->add_subcommand("analytic2d", "2D map of N micro-contacts (Fig. 3.7): plastic, separated "
                                                "(d_r ≥ d*, 3.25), combined (d_a ≤ d_r²/d*, 3.27)");
  two->add_option("--dr-over-dstar", a2->x_range, "Range MIN:MAX of the real contact size d_r/d* (default 0:3)");
  two->add_option("--da-over-dstar", a2->y_range, "Range MIN:MAX of the apparent contact size d_a/d* (default 0:6)");
  common(two, *a2, 301);
  add([a2]() { return run_analytic2d(*a2); });

  auto a3 = std::make_shared<MapArgs>();
  auto* three = cmd->add_subcommand("analytic3d", "3D map of two circular micro-contacts (Fig. 4.6): plastic, one "
                                                  "separated, two separated, combined, from R of (4.48)");
  three->add_option("--d-over-l", a3->x_range, "Range MIN:MAX of d/l, contact diameter over centre distance, "
                                               "within 0:1 (default 0:1)");
  three->add_option("--dstar-over-l", a3->y_range, "Range MIN:MAX of d*/l (default 0:2)");
  auto* interaction = three->add_option("--interaction", a3->interaction,
                                        "max (ν = 0.5, θ = 0: C_inter = 2/3) or min (ν = 0.5, θ = π/2: 1/3) (Fig. 4.6)")
                          ->check(CLI::IsMember({"max", "min"}));
  a3->nu_opt = three->add_option("--nu", a3->nu, "Poisson's ratio ν in (−1, 0.5] (default 0.5)");
  a3->theta_opt = three->add_option("--theta", a3->theta, "Angle θ between the load and the line of the centres "
                                                          "[rad] (default 0)");
  interaction->excludes(a3->nu_opt)->excludes(a3->theta_opt);
  common(three, *a3, 201);
  add([a3]() { return run_analytic3d(*a3); });

  add(add_wearmap_rough(*cmd));  // the numerical map of ch. 5

  return [cmd, commands]() {
    for (auto* sub : cmd->get_subcommands())
      if (commands->count(sub) != 0) return commands->at(sub)();
    return exit_bad_input;
  };
}

}  // namespace wearscale::app
