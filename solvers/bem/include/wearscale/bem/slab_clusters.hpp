#pragma once
// Micro-contacts of a contact map that the MPI ranks hold in slabs of rows,
// found without gathering the map: each rank labels the clusters of its own
// rows, and rank 0 joins the pieces that touch across the slabs' edges
// (periodic in both directions), keeping track of where each piece sits
// relative to the others. The clusters are find_clusters' on the whole map:
// the same points, areas, order and, for a cluster that does not wrap around
// the cell, the same centroid to the bit.
#include <cstddef>
#include <vector>

#include "wearscale/bem/contact_clusters.hpp"
#include "wearscale/core/field.hpp"

namespace wearscale::bem {

/// The micro-contacts of a map held in slabs, and which of them each point of
/// this rank's rows belongs to: find_clusters' ContactMap, cut in slabs.
struct SlabContactMap {
  std::vector<int> label;                ///< this rank's rows: the cluster's index in the sorted order, −1 outside
  std::vector<ContactCluster> clusters;  ///< rank 0's, sorted as find_clusters sorts them; empty elsewhere
  std::size_t count = 0;                 ///< how many clusters, on every rank
};

/// The clusters of {p > 0} of the whole grid `whole`, of which this rank
/// holds rows [first_row, first_row + rows.grid().nx) in `rows` (collective),
/// with this rank's labels. Serial: find_clusters(rows).
SlabContactMap label_clusters_slab(const RealField& rows, std::size_t first_row, const Grid2D& whole,
                                   Connectivity connectivity = Connectivity::Four);

/// The clusters alone: on rank 0 sorted by decreasing area as find_clusters
/// sorts them, empty on the other ranks (collective).
std::vector<ContactCluster> find_clusters_slab(const RealField& rows, std::size_t first_row, const Grid2D& whole,
                                               Connectivity connectivity = Connectivity::Four);

}  // namespace wearscale::bem
