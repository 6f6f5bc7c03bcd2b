#pragma once
// Worn-particle tagging of §7.2: each particle's interacting neighbours at a
// reference time are recorded (by particle id); later, a particle that has
// lost more than half of them is "worn".
#include <cstddef>
#include <cstdint>
#include <vector>

#include "wearscale/dem/bonds.hpp"

namespace wearscale::dem {

class WornParticles {
 public:
  /// Records the bonded neighbours of every particle now (the reference).
  WornParticles(const Particles& p, const Box& box, BondCriterion bond);

  /// For each current particle, the fraction of its reference neighbours
  /// that are no longer bonded to it (removed particles count as lost);
  /// 0 for a particle that had none or did not exist at the reference.
  std::vector<double> lost_fraction(const Particles& p, const Box& box) const;
  /// For each current particle: more than half of its reference neighbours
  /// lost (§7.2).
  std::vector<bool> worn(const Particles& p, const Box& box) const;
  std::size_t count_worn(const Particles& p, const Box& box) const;

  /// How many neighbours the particle of this id had at the reference
  /// (0 if unknown).
  std::size_t initial_neighbors(std::int64_t id) const;

 private:
  BondCriterion bond_;
  std::vector<std::int64_t> ids_;              // reference ids, sorted
  std::vector<std::size_t> offset_;            // CSR over ids_
  std::vector<std::int64_t> neighbor_;         // neighbour ids, sorted per particle
  std::size_t slot(std::int64_t id) const;     // index in ids_, or ids_.size()
};

}  // namespace wearscale::dem
