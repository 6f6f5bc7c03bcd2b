#pragma once
// A wear map: a regular grid over two dimensionless axes with, at every
// point, the region code (which outcome is energetically possible) and the
// energy ratios R behind it (thesis Fig. 3.7, 4.6, 5.4).
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace wearscale::wear {

/// n cells spanning [min, max]; the map samples their centres.
struct MapAxis {
  std::string name;   ///< dataset/column name, e.g. "d_over_l"
  std::string label;  ///< plot label, e.g. "d/l"
  double min = 0.0, max = 1.0;
  std::size_t n = 101;

  double value(std::size_t k) const { return min + (static_cast<double>(k) + 0.5) * (max - min) / static_cast<double>(n); }
  std::vector<double> values() const;
};

/// InputError naming the axis and the allowed range unless lo ≤ min < max ≤ hi
/// and 1 ≤ n ≤ 4096.
void check_axis(const MapAxis& axis, double lo, double hi);

/// A named value at every point of the map (row-major, y fastest: i·ny + j).
struct MapLayer {
  std::string name, description;
  std::vector<double> values;
};

struct WearMap {
  std::string kind;                                      ///< e.g. "analytic2d"
  std::string title;                                     ///< one line for plots and files
  MapAxis x, y;
  std::vector<int> region;                               ///< region code at (i, j), index i·ny + j
  std::vector<std::pair<int, std::string>> region_names;  ///< code → name, in code order
  std::vector<MapLayer> layers;                          ///< R of each case (and κ in 2D)
  std::vector<std::pair<std::string, double>> parameters;  ///< e.g. C_inter, ν, θ

  std::size_t index(std::size_t i, std::size_t j) const { return i * y.n + j; }
  /// Number of map points in region `code`.
  std::size_t count(int code) const;
  const MapLayer& layer(const std::string& name) const;  ///< std::out_of_range if absent
};

}  // namespace wearscale::wear
