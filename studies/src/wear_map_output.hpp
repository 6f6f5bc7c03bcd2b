#pragma once
// What the wear-map studies (wearmap/analytic2d, wearmap/analytic3d,
// wearmap/rough) share: axes over the ranges their keys give, recording the values a
// study resolved (defaults included) in its case, and the files of an
// analytic map (HDF5 + XDMF, CSV, the heat map of its regions).
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "wearscale/coupling/run_context.hpp"
#include "wearscale/io/config.hpp"
#include "wearscale/wear/wear_map.hpp"

namespace wearscale::studies {

/// `axis` over `range` ([MIN, MAX], as its key table read it) with `n` points.
wear::MapAxis axis_over(wear::MapAxis axis, std::pair<double, double> range, std::size_t n);

/// Records a resolved value in the case (so that to_json()/to_toml() hold
/// every parameter the run used, defaults included).
void record(Config& cfg, const std::string& key, const std::string& toml_value);
std::string toml_number(double v);
std::string toml_range(std::pair<double, double> r);

/// The region codes of `map` as a heat map figure wearmap_<kind> (PNG, PDF),
/// its table `csv` (a file name in the run's folder), palette entries named
/// after the regions: texts 1 title, 2 table, 3–6 the axes' ranges (x min,
/// x max, y min, y max), then those `lines` adds; `lines` are plot elements
/// drawn over the map (wearscale's text: numbers from texts by given_number(k)).
coupling::Figure heat_map_figure(const wear::WearMap& map, const std::string& title, const std::string& csv,
                                 const std::vector<std::string>& colours, const std::string& lines);
/// "one_separated" → "one separated" (gnuplot's enhanced text reads _ as a subscript).
std::string spaced(std::string name);

/// Writes an analytic map into the run's folder, wearmap_<kind>.h5 (+ .xdmf),
/// .csv and the figure `figure(csv)` makes (csv: the table's file name), and
/// reports each region's share of the map (fraction_<region>).
void publish_analytic_map(const Config& cfg, coupling::RunContext& context, const wear::WearMap& map,
                          const std::function<coupling::Figure(const std::string& csv)>& figure);

}  // namespace wearscale::studies
