#include "wearscale/dem/bonds.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

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

  // Wrapped positions and a grid of cells no smaller than the cutoff.
  std::vector<Vec3> x(p.position);
  std::array<int, 3> cells{};
  Vec3 lo{}, size{};
  for (int a = 0; a < 3; ++a) {
    const auto ua = static_cast<std::size_t>(a);
    double l = 0.0;
    if (box.periodic[ua]) {
      for (auto& xi : x) box.wrap(a, xi[a]);
      lo[a] = box.lo[a];
      l = box.hi[a] - box.lo[a];
      if (l < 2.0 * cut)
        throw InputError(fmt::format(
            "DEM pair search: the periodic length along {} is {:.6g}, shorter than twice the range "
            "{:.6g}; allowed: periodic lengths ≥ {:.6g}",
            "xyz"[a], l, cut, 2.0 * cut));
    } else {
      double mn = x[0][a], mx = x[0][a];
      for (const auto& xi : x) {
        mn = std::min(mn, xi[a]);
        mx = std::max(mx, xi[a]);
      }
      lo[a] = mn;
      l = std::max(mx - mn, cut) * (1.0 + 1e-12);
    }
    cells[ua] = std::clamp(static_cast<int>(std::floor(l / cut)), 1, 1 << 20);
    size[a] = l;
  }
  // No more cells than a few per particle (a lone particle far away on an
  // open axis would otherwise ask for a huge grid); cells only grow.
  auto product = [&] {
    return static_cast<double>(cells[0]) * static_cast<double>(cells[1]) * static_cast<double>(cells[2]);
  };
  while (product() > 4.0 * static_cast<double>(n) + 64.0) {
    auto& largest = *std::max_element(cells.begin(), cells.end());
    largest = std::max(1, largest / 2);
  }
  for (std::size_t a = 0; a < 3; ++a) size[static_cast<int>(a)] /= cells[a];
  const auto ncell = static_cast<std::size_t>(cells[0]) * static_cast<std::size_t>(cells[1]) *
                     static_cast<std::size_t>(cells[2]);
  auto coordinate = [&](const Vec3& xi, int a) {
    const int c = static_cast<int>(std::floor((xi[a] - lo[a]) / size[a]));
    return std::clamp(c, 0, cells[static_cast<std::size_t>(a)] - 1);
  };
  auto flat = [&](int cx, int cy, int cz) {
    return static_cast<std::size_t>(cx) +
           static_cast<std::size_t>(cells[0]) *
               (static_cast<std::size_t>(cy) + static_cast<std::size_t>(cells[1]) * static_cast<std::size_t>(cz));
  };
  // Particles sorted by cell (counting sort).
  std::vector<std::size_t> cell_of(n), start(ncell + 1, 0), order(n);
  for (std::size_t i = 0; i < n; ++i) {
    cell_of[i] = flat(coordinate(x[i], 0), coordinate(x[i], 1), coordinate(x[i], 2));
    ++start[cell_of[i] + 1];
  }
  for (std::size_t c = 0; c < ncell; ++c) start[c + 1] += start[c];
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) order[fill[cell_of[i]]++] = i;
  }
  std::vector<std::size_t> around;
  for (int cz = 0; cz < cells[2]; ++cz)
    for (int cy = 0; cy < cells[1]; ++cy)
      for (int cx = 0; cx < cells[0]; ++cx) {
        // The distinct cells around this one (grids of one or two cells
        // along an axis would otherwise list a cell twice).
        around.clear();
        for (int oz = -1; oz <= 1; ++oz)
          for (int oy = -1; oy <= 1; ++oy)
            for (int ox = -1; ox <= 1; ++ox) {
              std::array<int, 3> c{cx + ox, cy + oy, cz + oz};
              bool outside = false;
              for (std::size_t a = 0; a < 3; ++a) {
                if (c[a] >= 0 && c[a] < cells[a]) continue;
                if (!box.periodic[a]) {
                  outside = true;
                  break;
                }
                c[a] = (c[a] + cells[a]) % cells[a];
              }
              if (!outside) around.push_back(flat(c[0], c[1], c[2]));
            }
        std::sort(around.begin(), around.end());
        around.erase(std::unique(around.begin(), around.end()), around.end());
        const std::size_t home = flat(cx, cy, cz);
        for (std::size_t a = start[home]; a < start[home + 1]; ++a) {
          const std::size_t i = order[a];
          for (std::size_t other : around)
            for (std::size_t b = start[other]; b < start[other + 1]; ++b) {
              const std::size_t j = order[b];
              if (j <= i) continue;
              const Vec3 d = box.minimum_image(x[j] - x[i]);
              const double reach = p.radius[i] + p.radius[j] + range;
              if (dot(d, d) <= reach * reach) visit(i, j, d);
            }
        }
      }
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
  return out;
}

}  // namespace wearscale::dem
