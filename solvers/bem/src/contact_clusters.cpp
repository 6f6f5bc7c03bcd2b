#include "wearscale/bem/contact_clusters.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace wearscale::bem {

double contact_area(const RealField& p) {
  std::size_t n = 0;
  for (double v : p) n += v > 0.0 ? 1 : 0;
  return static_cast<double>(n) * p.grid().cell_area();
}

ContactMap find_clusters(const RealField& p, Connectivity connectivity) {
  const Grid2D& g = p.grid();
  const long nx = static_cast<long>(g.nx), ny = static_cast<long>(g.ny);
  ContactMap map;
  map.label.assign(g.size(), -1);
  // Breadth-first search on unwrapped coordinates: a cluster's points keep
  // their offset from the seed across periodic edges, so centroids are exact
  // for clusters smaller than the cell.
  struct Item {
    long i, j;  // unwrapped
  };
  std::vector<Item> queue;
  queue.reserve(g.size());
  std::vector<std::pair<long, long>> steps = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  if (connectivity == Connectivity::Eight) steps.insert(steps.end(), {{1, 1}, {1, -1}, {-1, 1}, {-1, -1}});
  std::vector<long> seen_at_i(g.size()), seen_at_j(g.size());  // unwrapped position where a point was reached

  for (long i0 = 0; i0 < nx; ++i0)
    for (long j0 = 0; j0 < ny; ++j0) {
      const std::size_t k0 = g.index(static_cast<std::size_t>(i0), static_cast<std::size_t>(j0));
      if (!(p[k0] > 0.0) || map.label[k0] >= 0) continue;
      const int id = static_cast<int>(map.clusters.size());
      ContactCluster c;
      double sx = 0.0, sy = 0.0;
      queue.clear();
      queue.push_back({i0, j0});
      map.label[k0] = id;
      seen_at_i[k0] = i0;
      seen_at_j[k0] = j0;
      for (std::size_t head = 0; head < queue.size(); ++head) {
        const Item it = queue[head];
        ++c.points;
        sx += static_cast<double>(it.i);
        sy += static_cast<double>(it.j);
        for (const auto& [di, dj] : steps) {
          const long ui = it.i + di, uj = it.j + dj;
          const std::size_t k = g.periodic_index(ui, uj);
          if (!(p[k] > 0.0)) continue;
          if (map.label[k] == id) {
            if (seen_at_i[k] != ui || seen_at_j[k] != uj) c.spans_cell = true;  // met itself around the torus
            continue;
          }
          map.label[k] = id;
          seen_at_i[k] = ui;
          seen_at_j[k] = uj;
          queue.push_back({ui, uj});
        }
      }
      c.area = static_cast<double>(c.points) * g.cell_area();
      const double cx = sx / static_cast<double>(c.points) * g.dx(), cy = sy / static_cast<double>(c.points) * g.dy();
      c.centroid_x = cx - std::floor(cx / g.lx) * g.lx;
      c.centroid_y = cy - std::floor(cy / g.ly) * g.ly;
      map.clusters.push_back(c);
    }

  // Largest first; relabel the map accordingly.
  std::vector<int> order(map.clusters.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return map.clusters[static_cast<std::size_t>(a)].points > map.clusters[static_cast<std::size_t>(b)].points; });
  std::vector<int> rank(order.size());
  std::vector<ContactCluster> sorted;
  sorted.reserve(order.size());
  for (std::size_t r = 0; r < order.size(); ++r) {
    rank[static_cast<std::size_t>(order[r])] = static_cast<int>(r);
    sorted.push_back(map.clusters[static_cast<std::size_t>(order[r])]);
  }
  for (int& l : map.label)
    if (l >= 0) l = rank[static_cast<std::size_t>(l)];
  map.clusters = std::move(sorted);
  return map;
}

}  // namespace wearscale::bem
