#include "wearscale/dem/surface_roughness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace wearscale::dem {

double arithmetic_roughness(const std::vector<double>& heights) {
  if (heights.empty()) return 0.0;
  const double mean = std::accumulate(heights.begin(), heights.end(), 0.0) / static_cast<double>(heights.size());
  double sum = 0.0;
  for (double h : heights) sum += std::abs(h - mean);
  return sum / static_cast<double>(heights.size());
}

std::vector<double> surface_heights(const Particles& p, const Box& box, const std::function<bool(std::size_t)>& chosen,
                                    Facing facing, double bin_width) {
  const double length = box.length().x;
  const auto bins = std::max<long>(1, std::lround(length / bin_width));
  const double w = length / static_cast<double>(bins);
  const double none = facing == Facing::up ? -std::numeric_limits<double>::infinity()
                                           : std::numeric_limits<double>::infinity();
  std::vector<double> edge(static_cast<std::size_t>(bins), none);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!chosen(i)) continue;
    auto k = static_cast<long>(std::floor((p.position[i].x - box.lo.x) / w)) % bins;
    if (k < 0) k += bins;
    double& e = edge[static_cast<std::size_t>(k)];
    e = facing == Facing::up ? std::max(e, p.position[i].z + p.radius[i]) : std::min(e, p.position[i].z - p.radius[i]);
  }
  std::vector<double> heights;
  heights.reserve(edge.size());
  for (double e : edge)
    if (std::isfinite(e)) heights.push_back(e);
  return heights;
}

double surface_roughness(const Particles& p, const Box& box, const std::function<bool(std::size_t)>& chosen,
                         Facing facing, double bin_width) {
  return arithmetic_roughness(surface_heights(p, box, chosen, facing, bin_width));
}

}  // namespace wearscale::dem
