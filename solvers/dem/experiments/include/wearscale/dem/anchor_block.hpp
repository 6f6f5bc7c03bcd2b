#pragma once
// The reference DEM benchmark of ../shared/bench/dem (in.dem_anchor.lammps):
// a dense HCP block of unit spheres overlapping their 12 neighbours by 0.5 %,
// periodic in x and y, two frozen layers at each end in z, the linear
// spring-dashpot law with history, dt = 0.05 √(2m/k_N). Built here exactly as
// the LAMMPS and LIGGGHTS decks build it, for side-by-side timings and a
// cross-check of the arithmetic.
#include "wearscale/dem/simulation.hpp"

namespace wearscale::dem {

struct AnchorBlock {
  int cells = 20;           ///< n: N = 4 n³ spheres
  int rebuild_every = 10;   ///< neighbour list rebuilt every this many steps, no check
  /// Particles renumbered in cell order every this many builds (0: never;
  /// NeighborSettings::renumber_every). The decks keep the lattice's order.
  int renumber_every = 0;
};

/// The deck's system, ready to run (walls frozen and fixed).
Simulation make_anchor_block(const AnchorBlock& spec);

}  // namespace wearscale::dem
