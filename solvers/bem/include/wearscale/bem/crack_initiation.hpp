#pragma once
// The crack initiation criterion (4.25) at the edges of micro-contacts
// (§4.2, Fig. 4.2): a wear particle can start at a micro-contact when the
// bottom solid has
//   σ_I ≥ σ_m   at its trailing edge (a)   (4.25a)  and
//   σ_III ≤ −σ_m at its leading edge (b)   (4.25b),
// σ_m the tensile strength. Under a tangential traction along ê, the edge
// behind the micro-contact (−ê side) is in tension and the edge ahead of it
// in compression. An edge is the pair of points across the contact border: a
// point of the micro-contact and its 4-neighbour out of it, behind (trailing)
// or ahead (leading) along ê.
#include <vector>

#include "wearscale/bem/contact_clusters.hpp"
#include "wearscale/bem/principal_stresses.hpp"

namespace wearscale::bem {

struct EdgeCrackCheck {
  double trailing_tension = 0.0;      ///< max σ_I on the trailing edge [Pa]
  double leading_compression = 0.0;   ///< min σ_III on the leading edge [Pa]
  bool trailing = false;              ///< (4.25a) holds
  bool leading = false;               ///< (4.25b) holds
  bool initiates() const { return trailing && leading; }  ///< (4.25)
};

/// (4.25) for every micro-contact of `map` (same order), with the principal
/// stresses `stress` (e.g. at the surface) and the sliding direction
/// (dir_x, dir_y) of the tangential traction on the bottom solid. A
/// micro-contact with no border across ê (it fills the cell along ê) has
/// trailing_tension = −∞ and leading_compression = +∞. InputError unless
/// σ_m > 0 and the direction is not zero.
std::vector<EdgeCrackCheck> crack_initiation(const ContactMap& map, const PrincipalStresses& stress, double dir_x,
                                             double dir_y, double tensile_strength);

}  // namespace wearscale::bem
