#pragma once
// The rows just outside a rank's slab of a periodic grid. The ranks hold the
// rows [0, R) in rank order, each a contiguous range (some none); a stencil
// that reaches one row across a slab's edge (the 4-neighbours of a point)
// needs the last row of the slab before and the first row of the slab after,
// the cell's last and first rows being neighbours. One process (or a serial
// build): its own last and first rows.
#include <cstddef>
#include <span>

#include "wearscale/core/row_exchange.hpp"

namespace wearscale {

/// Collective: this rank holds rows `mine` of a periodic grid of rows (the
/// ranks' ranges in rank order cover it once) and gives its first and last
/// rows (the same length on every rank; ignored when it holds none);
/// `before` receives the row just before its first, `after` the row just
/// after its last. std::invalid_argument if the ranges do not tile the rows.
void exchange_row_halo(RowRange mine, std::span<const double> first, std::span<const double> last,
                       std::span<double> before, std::span<double> after);

}  // namespace wearscale
