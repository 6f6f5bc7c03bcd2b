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

/// The clusters of {p > 0} of the whole grid `whole`, of which this rank
/// holds rows [first_row, first_row + rows.grid().nx) in `rows` (collective):
/// on rank 0 sorted by decreasing area as find_clusters sorts them, empty on
/// the other ranks. Serial: find_clusters(rows).clusters.
std::vector<ContactCluster> find_clusters_slab(const RealField& rows, std::size_t first_row, const Grid2D& whole,
                                               Connectivity connectivity = Connectivity::Four);

}  // namespace wearscale::bem
