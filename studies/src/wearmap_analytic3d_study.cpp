// The analytic 3D wear map of two circular micro-contacts (thesis ch. 4,
// Fig. 4.6) over [wearmap.analytic3d]: the regions plastic, one separated,
// two separated and combined from R ≥ 1 of (4.48) over (d/l, d*/l), at the
// interaction constant C_inter of (4.49). Outputs: wearmap_analytic3d.h5
// (+ .xdmf), .csv and the figure (.png, .pdf, with the lines R = 1).
//
//   [wearmap.analytic3d]
//   interaction = "max"          # ν = 0.5, θ = 0 (C_inter = 2/3); "min": θ = π/2 (1/3); or nu and theta
//   d_over_l = [0.0, 1.0]        # contact diameter over centre distance (d ≤ l)
//   dstar_over_l = [0.0, 2.0]    # critical diameter (4.35) over centre distance
//   n = 201                      # points along each axis (cell centres)
#include <numbers>

#include <fmt/format.h>

#include "wear_map_output.hpp"
#include "wearscale/coupling/palette.hpp"
#include "wearscale/coupling/plots.hpp"
#include "wearscale/studies/study.hpp"
#include "wearscale/studies/wearmap_keys.hpp"
#include "wearscale/wear/analytic_wear_maps.hpp"
#include "wearscale/wear/two_contacts_3d.hpp"

namespace wearscale::studies {

const KeyTable<WearmapAnalytic3dKeys>& wearmap_analytic3d_keys() {
  using K = WearmapAnalytic3dKeys;
  static const auto table =
      KeyTable<K>()
          .interval("d_over_l", &K::d_over_l, Range::closed(0.0, 1.0), units::dimensionless,
                    wear::default_d_over_l_axis().label, "range of d/l, contact diameter over centre distance")
          .flag("--d-over-l")
          .interval("dstar_over_l", &K::dstar_over_l, Range::non_negative(), units::dimensionless,
                    wear::default_dstar_over_l_axis().label,
                    "range of d*/l, critical diameter (4.35) over centre distance")
          .flag("--dstar-over-l")
          .integer("n", &K::n, Range::closed(2, 4096), "points along each axis")
          .flag("--n")
          .custom("interaction", "choice", "max | min", "",
                  "max (ν = 0.5, θ = 0: C_inter = 2/3) or min (ν = 0.5, θ = π/2: 1/3) (Fig. 4.6); excludes nu and "
                  "theta",
                  [](const Config& c, const std::string& key, K& k) {
                    if (c.has(key)) k.interaction = c.choice(key, {"max", "min"});
                  })
          .flag("--interaction")
          .number("nu", &K::nu, Range::open_closed(-1.0, 0.5), "Poisson's ratio ν")
          .flag("--nu")
          .number("theta", &K::theta, Range::any(), "angle θ between the load and the line of the centres")
          .unit("rad")
          .flag("--theta")
          .then([](const Config& c, K& k) {
            if (k.interaction.empty()) return;
            // Fig. 4.6: ν = ½ with θ = 0 (most) or π/2 (least)
            for (const char* fixed : {"nu", "theta"})
              if (c.has(fixed))
                throw c.error(fixed, "cannot be set together with interaction (which fixes ν = 0.5 and θ)",
                              "either interaction, or nu and theta");
            k.nu = 0.5;
            k.theta = k.interaction == "max" ? 0.0 : std::numbers::pi / 2;
          });
  return table;
}

namespace {

namespace fs = std::filesystem;
namespace oi = coupling::okabe_ito;

coupling::Figure figure_3d(const wear::WearMap& map, double c_inter, const std::string& csv) {
  // Fig. 4.6: the lines R = 1 of (4.48) at this C_inter (solid) and at the other bound (dashed), and d = d*,
  // each case's line in the full colour of the region it bounds (filled tinted halfway to white). The
  // constants C_inter are texts 7 (the case's) and 8 (the other bound).
  constexpr double fill = 0.5;
  const double other = c_inter > 0.5 ? wear::min_interaction_constant : wear::max_interaction_constant;
  std::string lines;
  const char* colours[] = {oi::blue, oi::bluish_green, oi::vermillion};
  for (const int c : {7, 8})
    for (std::size_t k = 0; k < wear::particle_cases.size(); ++k) {
      const auto d = wear::particle_cases[k];
      const std::string c_case = d == wear::ParticleCase::OneSeparated   ? "1"
                                 : d == wear::ParticleCase::TwoSeparated ? "0.5"
                                                                         : "(x/(1+x))**2";
      lines += fmt::format(", \\\n  ({:g} + 3*pi/8*given_number({})*x)*x*{} with lines lw 2 dt {} lc rgb \"{}\" "
                           "title sprintf(\"{}, C_{{inter}} = %.3g\", given_number({}))",
                           wear::count_constant(d), c, c_case, c == 7 ? 1 : 2, colours[k], spaced(wear::name(d)), c);
    }
  auto f = heat_map_figure(
      map, fmt::format("3D wear map of two micro-contacts, R ≥ 1 (4.48) at C_{{inter}} = {:.4g} (thesis Fig. 4.6)", c_inter),
      csv, {"#F7F7F7", oi::tint(oi::sky_blue, fill), oi::tint(oi::bluish_green, fill), oi::tint(oi::orange, fill)},
      lines + ", \\\n  x with lines lw 1 dt 3 lc rgb \"black\" title \"d = d*\"");
  f.add("C_inter", c_inter);
  f.add("C_inter, the other bound", other);
  return f;
}

class WearmapAnalytic3d final : public Study {
 public:
  std::string name() const override { return "wearmap/analytic3d"; }
  std::string summary() const override {
    return "3D map of two circular micro-contacts (Fig. 4.6): plastic, one separated, two separated, combined, from "
           "R of (4.48)";
  }
  std::string default_case_name() const override { return "wearmap"; }
  std::string default_output_dir() const override { return "out/wearmap-analytic3d"; }  // each map its own folder
  Schema schema() const override { return wearmap_analytic3d_keys().schema("wearmap.analytic3d"); }

  std::vector<std::string> prepare(Config& cfg) override {
    const std::string k = "wearmap.analytic3d.";
    WearmapAnalytic3dKeys keys;
    wearmap_analytic3d_keys().read(cfg.section("wearmap.analytic3d"), keys);
    const std::size_t n = keys.n;
    x_ = axis_over(wear::default_d_over_l_axis(), keys.d_over_l, n);
    y_ = axis_over(wear::default_dstar_over_l_axis(), keys.dstar_over_l, n);
    const double nu = keys.nu, theta = keys.theta;
    const bool interaction = !keys.interaction.empty();
    cfg.reject_unknown_keys();
    record(cfg, k + "n", fmt::format("{}", n));
    record(cfg, k + "d_over_l", toml_range({x_.min, x_.max}));
    record(cfg, k + "dstar_over_l", toml_range({y_.min, y_.max}));
    if (!interaction) {
      record(cfg, k + "nu", toml_number(nu));
      record(cfg, k + "theta", toml_number(theta));
    }
    c_inter_ = wear::interaction_constant(nu, theta);  // (4.49)
    return {};
  }

  void run(const Config& cfg, RunContext& context) override {
    const auto map = wear::analytic_map_3d(x_, y_, c_inter_);
    context.report("C_inter", c_inter_, "1", "interaction constant (1 − ν sin²θ)/(2 − ν) (4.49)");
    // Adjacent contacts (d = l): the smallest d/d* of each case, 1/boundary(1).
    for (const auto d : wear::particle_cases)
      context.report(fmt::format("least_d_{}", wear::name(d)), 1.0 / wear::boundary_dstar_over_l(d, 1.0, c_inter_),
                     "1", fmt::format("least d/d* of two adjacent contacts (d = l) for {} (4.48)", wear::name(d)));
    publish_analytic_map(cfg, context, map, [&](const std::string& csv) { return figure_3d(map, c_inter_, csv); });
  }

 private:
  wear::MapAxis x_, y_;
  double c_inter_ = 0.0;
};

}  // namespace
}  // namespace wearscale::studies

WEARSCALE_STUDY(WearmapAnalytic3d)
