#include "wearscale/dem/clusters.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>

namespace wearscale::dem {

namespace {
// Disjoint sets with path halving and union by size.
class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n), size_(n, 1) { std::iota(parent_.begin(), parent_.end(), 0); }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i) {
      parent_[i] = parent_[parent_[i]];
      i = parent_[i];
    }
    return i;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
  }

 private:
  std::vector<std::size_t> parent_, size_;
};

template <class T>
void sort_unique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}
}  // namespace

ClusterAnalysis find_clusters(const Particles& p, const Box& box, const BondCriterion& bond) {
  const std::size_t n = p.size();
  const auto pairs = bonded_pairs(p, box, bond);
  UnionFind sets(n);
  for (const auto& [i, j] : pairs) sets.unite(i, j);
  std::map<int, std::size_t> first_of_wall;  // a rigid wall is one solid
  for (std::size_t i = 0; i < n; ++i) {
    if (p.wall[i] == no_wall) continue;
    const auto [it, added] = first_of_wall.emplace(p.wall[i], i);
    if (!added) sets.unite(it->second, i);
  }

  ClusterAnalysis out;
  out.label.assign(n, 0);
  std::vector<std::size_t> root_cluster(n, n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t r = sets.find(i);
    if (root_cluster[r] == n) {
      root_cluster[r] = out.clusters.size();
      out.clusters.emplace_back();
    }
    out.label[i] = root_cluster[r];
    out.clusters[root_cluster[r]].members.push_back(i);
  }

  // Unwrapped positions: a breadth-first walk along the bonds from each
  // cluster's first member, adding nearest-image separations.
  std::vector<std::size_t> offset(n + 1, 0), adjacency(2 * pairs.size());
  for (const auto& [i, j] : pairs) {
    ++offset[i + 1];
    ++offset[j + 1];
  }
  std::partial_sum(offset.begin(), offset.end(), offset.begin());
  {
    std::vector<std::size_t> fill(offset.begin(), offset.end() - 1);
    for (const auto& [i, j] : pairs) {
      adjacency[fill[i]++] = j;
      adjacency[fill[j]++] = i;
    }
  }
  std::vector<Vec3> unwrapped(p.position);
  std::vector<char> seen(n, 0);
  std::vector<std::size_t> queue;
  for (auto& c : out.clusters) {
    // Members reached by no bond (wall particles joined only as one wall)
    // start their own walk, from their own position.
    for (std::size_t start : c.members) {
      if (seen[start]) continue;
      seen[start] = 1;
      queue.assign(1, start);
      for (std::size_t q = 0; q < queue.size(); ++q) {
        const std::size_t i = queue[q];
        for (std::size_t k = offset[i]; k < offset[i + 1]; ++k) {
          const std::size_t j = adjacency[k];
          if (seen[j]) continue;
          seen[j] = 1;
          unwrapped[j] = unwrapped[i] + box.minimum_image(p.position[j] - p.position[i]);
          queue.push_back(j);
        }
      }
    }
    Vec3 moment{};
    double volume = 0.0;
    for (std::size_t i : c.members) {
      c.mass += p.mass[i];
      moment += p.mass[i] * unwrapped[i];
      volume += 4.0 / 3.0 * std::numbers::pi * p.radius[i] * p.radius[i] * p.radius[i];
      c.bodies.push_back(p.body[i]);
      if (p.wall[i] != no_wall) c.walls.push_back(p.wall[i]);
    }
    c.center = (1.0 / c.mass) * moment;
    for (int a = 0; a < 3; ++a) box.wrap(a, c.center[a]);
    c.equivalent_diameter = std::cbrt(6.0 * volume / std::numbers::pi);
    sort_unique(c.bodies);
    sort_unique(c.walls);
  }

  // Largest first; relabel the particles accordingly.
  std::vector<std::size_t> order(out.clusters.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return out.clusters[a].size() > out.clusters[b].size();
  });
  std::vector<std::size_t> rank(order.size());
  std::vector<Cluster> sorted;
  sorted.reserve(order.size());
  for (std::size_t r = 0; r < order.size(); ++r) {
    rank[order[r]] = r;
    sorted.push_back(std::move(out.clusters[order[r]]));
  }
  out.clusters = std::move(sorted);
  for (auto& l : out.label) l = rank[l];
  return out;
}

}  // namespace wearscale::dem
