#pragma once
// Micro-contacts: the connected clusters of contact points of a periodic
// contact map, with their areas and centroids.
#include <cstddef>
#include <vector>

#include "wearscale/core/field.hpp"

namespace wearscale::bem {

enum class Connectivity { Four, Eight };

struct ContactCluster {
  std::size_t points = 0;
  double area = 0.0;                     ///< points × cell area [m²]
  double centroid_x = 0.0, centroid_y = 0.0;  ///< in [0, Lx) × [0, Ly), periodic-aware
  bool spans_cell = false;               ///< wraps around the periodic cell (percolates)
};

struct ContactMap {
  std::vector<int> label;  ///< cluster index of each grid point, −1 outside the contact
  std::vector<ContactCluster> clusters;  ///< sorted by decreasing area
};

/// Real contact area Σ_{p>0} ΔA.
double contact_area(const RealField& pressure);

/// Labels the connected clusters of {p > 0}, joining across periodic edges.
ContactMap find_clusters(const RealField& pressure, Connectivity connectivity = Connectivity::Four);

}  // namespace wearscale::bem
