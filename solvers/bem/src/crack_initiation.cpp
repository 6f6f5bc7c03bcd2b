#include "wearscale/bem/crack_initiation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::bem {

std::vector<EdgeCrackCheck> crack_initiation(const ContactMap& map, const PrincipalStresses& stress, double dir_x,
                                             double dir_y, double sigma_m) {
  if (!(sigma_m > 0.0) || !std::isfinite(sigma_m))
    throw InputError(fmt::format("crack initiation: tensile strength σ_m = {} Pa is not allowed; allowed: σ_m > 0",
                                 sigma_m));
  const double norm = std::hypot(dir_x, dir_y);
  if (!(norm > 0.0) || !std::isfinite(norm))
    throw InputError("crack initiation: the sliding direction is zero or not finite");
  const Grid2D& g = stress.first.grid();
  if (map.label.size() != g.size()) throw std::invalid_argument("crack_initiation: contact map and stresses differ");
  const double ex = dir_x / norm, ey = dir_y / norm;
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::vector<EdgeCrackCheck> out(map.clusters.size());
  for (auto& c : out) {
    c.trailing_tension = -inf;
    c.leading_compression = inf;
  }
  const long steps[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) {
      const std::size_t k = g.index(i, j);
      const int id = map.label[k];
      if (id < 0) continue;
      EdgeCrackCheck& c = out[static_cast<std::size_t>(id)];
      for (const auto& step : steps) {
        const std::size_t kn =
            g.periodic_index(static_cast<long>(i) + step[0], static_cast<long>(j) + step[1]);
        if (map.label[kn] == id) continue;  // inside the same micro-contact: no border
        const double along = static_cast<double>(step[0]) * g.dx() * ex + static_cast<double>(step[1]) * g.dy() * ey;
        if (along < -1e-12 * g.dx())  // the neighbour lies behind: trailing edge (a)
          c.trailing_tension = std::max({c.trailing_tension, stress.first[k], stress.first[kn]});
        else if (along > 1e-12 * g.dx())  // ahead: leading edge (b)
          c.leading_compression = std::min({c.leading_compression, stress.third[k], stress.third[kn]});
      }
    }
  for (auto& c : out) {
    c.trailing = c.trailing_tension >= sigma_m;       // (4.25a)
    c.leading = c.leading_compression <= -sigma_m;    // (4.25b)
  }
  return out;
}

}  // namespace wearscale::bem
