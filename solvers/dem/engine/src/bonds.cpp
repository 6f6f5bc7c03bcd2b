#include "wearscale/dem/bonds.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "wearscale/dem/cell_grid.hpp"

namespace wearscale::dem {

BondCriterion BondCriterion::contact(double gap) { return {gap, {}}; }

BondCriterion BondCriterion::cohesive(const CohesiveLaw& law, double max_radius) {
  BondCriterion b;
  b.max_gap = law.reach(max_radius);
  b.gap = [law](const Particles& p, std::size_t i, std::size_t j) {
    return fracture_separation(law.pair_material(p.material[i], p.material[j]), p.radius[i] + p.radius[j]);  // (6.57)
  };
  return b;
}

void for_each_close_pair(const Particles& p, const Box& box, double range,
                         const std::function<void(std::size_t, std::size_t, const Vec3&)>& visit) {
  const std::size_t n = p.size();
  if (n < 2) return;
  double max_radius = 0.0;
  for (double r : p.radius) max_radius = std::max(max_radius, r);
  const double cut = 2.0 * max_radius + std::max(range, 0.0);
  // Wrapped positions (the particles may be read back, or between builds).
  std::vector<Vec3> x(p.position);
  for (int a = 0; a < 3; ++a)
    if (box.periodic[static_cast<std::size_t>(a)])
      for (auto& xi : x) box.wrap(a, xi[a]);
  CellGrid grid;
  grid.build(x, box, cut);
  grid.for_each_candidate(x, [&](std::uint32_t i, std::uint32_t j, std::uint8_t, const Vec3& d) {
    if (i == j) return;  // a particle and its own image
    const double reach = p.radius[i] + p.radius[j] + range;
    if (dot(d, d) > reach * reach) return;
    if (i < j)
      visit(i, j, d);
    else
      visit(j, i, -d);
  });
}

std::vector<std::pair<std::size_t, std::size_t>> bonded_pairs(const Particles& p, const Box& box,
                                                              const BondCriterion& bond) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for_each_close_pair(p, box, bond.max_gap, [&](std::size_t i, std::size_t j, const Vec3& d) {
    const double gap = norm(d) - p.radius[i] - p.radius[j];
    const double limit = bond.gap ? bond.gap(p, i, j) : bond.max_gap;
    if (gap <= limit) out.emplace_back(i, j);
  });
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());  // bonded through several images
  return out;
}

}  // namespace wearscale::dem
