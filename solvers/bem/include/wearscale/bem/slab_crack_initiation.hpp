#pragma once
// The crack initiation criterion (4.25) per micro-contact (crack_initiation.hpp)
// on a contact map that the MPI ranks hold in slabs of rows: each rank walks
// the edges of its own rows, with the row on either side of its slab from the
// neighbouring ranks, and the ranks' extremes are combined per micro-contact.
// Maxima and minima do not depend on the order they are taken in, so every
// figure is the whole map's to the bit.
#include <cstddef>
#include <vector>

#include "wearscale/bem/crack_initiation.hpp"
#include "wearscale/bem/slab_clusters.hpp"

namespace wearscale::bem {

/// (4.25) for every micro-contact of the whole grid `whole` (collective), of
/// which this rank holds rows [first_row, first_row + rows) of the labels
/// (`map`, from label_clusters_slab) and of the principal stresses `stress`:
/// on every rank, in the clusters' order. Serial: crack_initiation. InputError
/// unless σ_m > 0 and the direction is not zero.
std::vector<EdgeCrackCheck> crack_initiation_slab(const SlabContactMap& map, const PrincipalStresses& stress,
                                                  std::size_t first_row, const Grid2D& whole, double dir_x,
                                                  double dir_y, double tensile_strength);

}  // namespace wearscale::bem
