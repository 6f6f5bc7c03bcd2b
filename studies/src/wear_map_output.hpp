#pragma once
// What the wear-map studies (wearmap/analytic2d, wearmap/analytic3d,
// wearmap/rough) share: axis-range keys [MIN, MAX], recording the values a
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

/// An axis range key: two numbers [MIN, MAX], each in `element`, MIN < MAX;
/// `fallback` when absent. `what` (e.g. "d/l") names the quantity in errors.
std::pair<double, double> read_range(const Config& cfg, const std::string& key, std::pair<double, double> fallback,
                                     const Range& element, const std::string& what);

/// `axis` with the range of the case key `key` (when set) and `n` points.
wear::MapAxis read_axis(const Config& cfg, const std::string& key, wear::MapAxis axis, std::size_t n,
                        const Range& element);

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
