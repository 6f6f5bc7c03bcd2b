#pragma once
// Clusters of bonded particles (connected components of the bond graph):
// detached wear particles are the clusters that touch no wall (§6.3, §7.2).
// The particles of one rigid wall always belong to one cluster.
#include <cstddef>
#include <vector>

#include "wearscale/dem/bonds.hpp"

namespace wearscale::dem {

struct Cluster {
  std::vector<std::size_t> members;  ///< particle indices, increasing
  double mass = 0.0;
  /// Centre of mass, with the members unwrapped across periodic boundaries
  /// along the bonds, then wrapped back into the box.
  Vec3 center{};
  /// Diameter of the sphere of the members' solid volume Σ 4πr³/3.
  double equivalent_diameter = 0.0;
  std::vector<int> bodies;  ///< the distinct body tags of its members, increasing
  std::vector<int> walls;   ///< the distinct walls it contains, increasing

  std::size_t size() const { return members.size(); }
  bool touches_wall() const { return !walls.empty(); }
};

struct ClusterAnalysis {
  std::vector<Cluster> clusters;  ///< largest first (ties: lowest first member)
  std::vector<std::size_t> label; ///< each particle's cluster (index into clusters)
};

/// The connected components of the bonded pairs (union-find).
ClusterAnalysis find_clusters(const Particles& p, const Box& box, const BondCriterion& bond);

}  // namespace wearscale::dem
