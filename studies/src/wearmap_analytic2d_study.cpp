// The analytic 2D wear map of N micro-contacts (thesis ch. 3, Fig. 3.7) over
// [wearmap.analytic2d]: the regions plastic, separated (d_r ≥ d*, 3.25) and
// combined (d_a ≤ d_r²/d*, 3.27) over (d_r/d*, d_a/d*). Outputs:
// wearmap_analytic2d.h5 (+ .xdmf), .csv and the figure (.png, .pdf, with the lines).
//
//   [wearmap.analytic2d]
//   dr_over_dstar = [0.0, 3.0]   # real contact size d_r/d*
//   da_over_dstar = [0.0, 6.0]   # apparent contact size d_a/d*
//   n = 301                      # points along each axis (cell centres)
#include <fmt/format.h>

#include "wear_map_output.hpp"
#include "wearscale/coupling/palette.hpp"
#include "wearscale/coupling/plots.hpp"
#include "wearscale/studies/study.hpp"
#include "wearscale/studies/wearmap_keys.hpp"
#include "wearscale/wear/analytic_wear_maps.hpp"

namespace wearscale::studies {

const KeyTable<WearmapAnalytic2dKeys>& wearmap_analytic2d_keys() {
  using K = WearmapAnalytic2dKeys;
  static const auto table =
      KeyTable<K>()
          .interval("dr_over_dstar", &K::dr_over_dstar, Range::non_negative(), units::dimensionless,
                    wear::default_real_size_axis().label, "range of the real contact size d_r/d*")
          .flag("--dr-over-dstar")
          .interval("da_over_dstar", &K::da_over_dstar, Range::non_negative(), units::dimensionless,
                    wear::default_apparent_size_axis().label, "range of the apparent contact size d_a/d*")
          .flag("--da-over-dstar")
          .integer("n", &K::n, Range::closed(2, 4096), "points along each axis")
          .flag("--n");
  return table;
}

namespace {

namespace fs = std::filesystem;
namespace oi = coupling::okabe_ito;

coupling::Figure figure_2d(const wear::WearMap& map, const std::string& csv) {
  // Fig. 3.7: d_r = d* (3.25) and d_a = d_r²/d* (3.27) where d_a ≥ d_r, and d_a = d_r (a single contact).
  // Fills: neutral greys for the inaccessible (d_a < d_r) and plastic regions, the wear regions tinted
  // halfway to white, so that the lines, drawn in the full colours, show over them.
  constexpr double fill = 0.5;
  return heat_map_figure(map, "2D wear map of N micro-contacts (thesis Fig. 3.7)", csv,
                         {"#BBBBBB", "#F7F7F7", oi::tint(oi::sky_blue, fill), oi::tint(oi::orange, fill)},
                         fmt::format(", \\\n  \"+\" using (1):(1 + $0/999*(given_number(6) - 1)) with lines lw 2 dt 2 lc rgb "
                                     "\"black\" title \"d_r = d* (3.25)\""
                                     ", \\\n  (x >= 1 ? x*x : NaN) with lines lw 2 dt 2 lc rgb \"{}\" title "
                                     "\"d_a = d_r^2/d* (3.27)\", \\\n"
                                     "  x with lines lw 1 lc rgb \"black\" title \"d_a = d_r (one contact)\"",
                                     oi::blue));
}

class WearmapAnalytic2d final : public Study {
 public:
  std::string name() const override { return "wearmap/analytic2d"; }
  std::string summary() const override {
    return "2D map of N micro-contacts (Fig. 3.7): plastic, separated (d_r ≥ d*, 3.25), combined (d_a ≤ d_r²/d*, "
           "3.27)";
  }
  std::string default_case_name() const override { return "wearmap"; }
  std::string default_output_dir() const override { return "out/wearmap-analytic2d"; }  // each map its own folder
  Schema schema() const override { return wearmap_analytic2d_keys().schema("wearmap.analytic2d"); }

  std::vector<std::string> prepare(Config& cfg) override {
    const std::string k = "wearmap.analytic2d.";
    WearmapAnalytic2dKeys keys;
    wearmap_analytic2d_keys().read(cfg.section("wearmap.analytic2d"), keys);
    const std::size_t n = keys.n;
    x_ = axis_over(wear::default_real_size_axis(), keys.dr_over_dstar, n);
    y_ = axis_over(wear::default_apparent_size_axis(), keys.da_over_dstar, n);
    cfg.reject_unknown_keys();
    record(cfg, k + "n", fmt::format("{}", n));
    record(cfg, k + "dr_over_dstar", toml_range({x_.min, x_.max}));
    record(cfg, k + "da_over_dstar", toml_range({y_.min, y_.max}));
    return {};
  }

  void run(const Config& cfg, RunContext& context) override {
    const auto map = wear::analytic_map_2d(x_, y_);
    publish_analytic_map(cfg, context, map, [&](const std::string& csv) { return figure_2d(map, csv); });
  }

 private:
  wear::MapAxis x_, y_;
};

}  // namespace
}  // namespace wearscale::studies

WEARSCALE_STUDY(WearmapAnalytic2d)
