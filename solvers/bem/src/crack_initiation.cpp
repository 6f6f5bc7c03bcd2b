#include "wearscale/bem/crack_initiation.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "edge_walk.hpp"
#include "wearscale/core/errors.hpp"

namespace wearscale::bem {

namespace detail {

std::array<double, 2> sliding_direction(double dir_x, double dir_y, double sigma_m) {
  if (!(sigma_m > 0.0) || !std::isfinite(sigma_m))
    throw InputError(fmt::format("crack initiation: tensile strength σ_m = {} Pa is not allowed; allowed: σ_m > 0",
                                 sigma_m));
  const double norm = std::hypot(dir_x, dir_y);
  if (!(norm > 0.0) || !std::isfinite(norm))
    throw InputError("crack initiation: the sliding direction is zero or not finite");
  return {dir_x / norm, dir_y / norm};
}

std::vector<EdgeCrackCheck> unmet_edges(std::size_t clusters) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::vector<EdgeCrackCheck> checks(clusters);
  for (auto& c : checks) {
    c.trailing_tension = -inf;
    c.leading_compression = inf;
  }
  return checks;
}

void decide(std::vector<EdgeCrackCheck>& checks, double sigma_m) {
  for (auto& c : checks) {
    c.trailing = c.trailing_tension >= sigma_m;     // (4.25a)
    c.leading = c.leading_compression <= -sigma_m;  // (4.25b)
  }
}

}  // namespace detail

std::vector<EdgeCrackCheck> crack_initiation(const ContactMap& map, const PrincipalStresses& stress, double dir_x,
                                             double dir_y, double sigma_m) {
  const auto e = detail::sliding_direction(dir_x, dir_y, sigma_m);
  const Grid2D& g = stress.first.grid();
  if (map.label.size() != g.size()) throw std::invalid_argument("crack_initiation: contact map and stresses differ");
  std::vector<EdgeCrackCheck> checks = detail::unmet_edges(map.clusters.size());
  const long nx = static_cast<long>(g.nx);
  detail::walk_edges(g.nx, g, e, [&](long i) {  // the cell is periodic along x too
    const std::size_t at = static_cast<std::size_t>((i + nx) % nx) * g.ny;
    return detail::MapRow{map.label.data() + at, stress.first.data() + at, stress.third.data() + at};
  }, checks);
  detail::decide(checks, sigma_m);
  return checks;
}

}  // namespace wearscale::bem
