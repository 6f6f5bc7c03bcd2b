#include "wearscale/wear/wear_map.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::wear {

std::vector<double> MapAxis::values() const {
  std::vector<double> v(n);
  for (std::size_t k = 0; k < n; ++k) v[k] = value(k);
  return v;
}

void check_axis(const MapAxis& axis, double lo, double hi) {
  if (!(std::isfinite(axis.min) && std::isfinite(axis.max) && axis.min >= lo && axis.max <= hi &&
        axis.min < axis.max))
    throw InputError(fmt::format("wear map axis {}: range {}:{} is not allowed; allowed: {} ≤ min < max ≤ {}",
                                 axis.label, axis.min, axis.max, lo, hi));
  if (axis.n < 1 || axis.n > 4096)
    throw InputError(fmt::format("wear map axis {}: {} points is not allowed; allowed: 1 … 4096", axis.label, axis.n));
}

std::size_t WearMap::count(int code) const {
  return static_cast<std::size_t>(std::count(region.begin(), region.end(), code));
}

const MapLayer& WearMap::layer(const std::string& name) const {
  for (const auto& l : layers)
    if (l.name == name) return l;
  throw std::out_of_range(fmt::format("wear map {} has no layer '{}'", kind, name));
}

}  // namespace wearscale::wear
