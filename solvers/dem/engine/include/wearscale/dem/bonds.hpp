#pragma once
// Which particles are bonded: pairs whose gap δ_N = |x_j − x_i| − r_i − r_j
// is at most a limit, by default the cohesive range δ_f of the pair (the
// "interacting neighbours" of §7.2). Worn-particle tagging and cluster
// analysis are built on these bonds.
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "wearscale/dem/box.hpp"
#include "wearscale/dem/cohesive_law.hpp"
#include "wearscale/dem/particles.hpp"

namespace wearscale::dem {

struct BondCriterion {
  /// The largest gap of any pair (the search range beyond contact).
  double max_gap = 0.0;
  /// The gap limit of pair (i, j), at most max_gap; empty: max_gap for all.
  std::function<double(const Particles&, std::size_t, std::size_t)> gap;

  /// Bonded when the gap is at most `gap` (0: touching or overlapping).
  static BondCriterion contact(double gap = 0.0);
  /// Bonded while the cohesive force acts: δ_N ≤ δ_f of the pair (6.57),
  /// whether or not cohesion is switched on in `law`. `max_radius` bounds the
  /// radii the criterion will see (δ_f grows with r_i + r_j above d_c).
  static BondCriterion cohesive(const CohesiveLaw& law, double max_radius);
};

/// The bonded pairs (i < j), in increasing (i, j), each once: bonded when
/// any periodic image of j is (on a periodic axis thinner than the range a
/// pair may be bonded through several).
std::vector<std::pair<std::size_t, std::size_t>> bonded_pairs(const Particles& p, const Box& box,
                                                              const BondCriterion& bond);

/// Calls visit(i, j, d) once for every pair i < j and periodic image of j
/// at most r_i + r_j + range apart (d = x_j + shift − x_i; one image per
/// pair unless a periodic length is below 2 r_max + range). A cell-list
/// search over a wrapped copy of the positions: works on any particles,
/// e.g. read back.
void for_each_close_pair(const Particles& p, const Box& box, double range,
                         const std::function<void(std::size_t, std::size_t, const Vec3&)>& visit);

}  // namespace wearscale::dem
