#pragma once
// Particles numbered along the cells of a grid: the permutation that sorts
// them by cell, layer by layer in z, row by row in y, then along x. A
// system numbered so has the pairs of its neighbour list close in index
// (their particles' data shares cache lines, and the threaded pair loop can
// split the rows into blocks instead of keeping per-thread force buffers).
// A randomly inserted sample — the carved amorphous SiO2 — is not.
#include <cstddef>
#include <span>
#include <vector>

#include "wearscale/dem/vec3.hpp"

namespace wearscale::dem {

/// order[k] = the particle to number k: by cubic cells of side `cell` over
/// the particles' bounding box (z, then y, then x), in increasing index
/// within a cell (stable). `cell` > 0. Cells of about half the largest
/// diameter number best: a shuffled 256 000-sphere block of diameter d ran at
/// 7.1-7.5 M particle-steps per CPU-second renumbered with cells of 0.6 d,
/// 5.8-6.4 with 1.2 d, 4.5-4.8 with 2.4 d and 5.1-5.3 with 0.3 d (bench_dem,
/// CohesiveRenumbered/40): thin layers keep a particle's neighbours in the
/// next layers close in index, thinner ones split its own row.
std::vector<std::size_t> cell_order(std::span<const Vec3> positions, double cell);

}  // namespace wearscale::dem
