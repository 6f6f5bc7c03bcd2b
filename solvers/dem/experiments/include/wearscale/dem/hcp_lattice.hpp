#pragma once
// Hexagonal close-packed lattice sites, in the orthogonal 4-site cell
// a × √3a × √(8/3)a (a: nearest-neighbour distance) that LAMMPS' `lattice hcp`
// uses, so that decks and wearscale build the same block.
#include <vector>

#include "wearscale/dem/box.hpp"
#include "wearscale/dem/vec3.hpp"

namespace wearscale::dem {

struct HcpLattice {
  double spacing = 1.0;  ///< nearest-neighbour distance a
  int nx = 1, ny = 1, nz = 1;  ///< cells along x, y, z

  /// Cell edge lengths a, √3 a, √(8/3) a.
  Vec3 cell() const;
  /// Sites, z slowest then y then x then basis (LAMMPS create_atoms order),
  /// with the lowest layer at z = 0.
  std::vector<Vec3> sites() const;
  /// The box that makes the block periodic: [0, nx a) × [0, ny √3 a) ×
  /// [−c/4, (nz − ¼) c) with c = √(8/3) a (periodic in all three axes).
  Box box() const;
};

}  // namespace wearscale::dem
