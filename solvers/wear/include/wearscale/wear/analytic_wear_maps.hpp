#pragma once
// The analytic wear maps of thesis ch. 3 and 4, sampled on a grid.
//
// 2D (Fig. 3.7): axes d_r/d* and d_a/d*; regions inaccessible (−1, d_a < d_r),
// plastic (0), separated (1, (3.25)) and combined (2, (3.27)); layers R_sep
// (3.24), R_comb (3.26), κ (3.28) and κ_min (3.29).
// 3D (Fig. 4.6): axes d/l and d*/l at one interaction constant C_inter (4.49);
// regions plastic (0), one separated (1), two separated (2) and combined (3);
// layers R (4.48) of each detachment.
#include "wearscale/wear/wear_map.hpp"

namespace wearscale::wear {

/// Default axes of Fig. 3.7 and Fig. 4.6.
MapAxis default_real_size_axis();      ///< d_r/d* over [0, 3]
MapAxis default_apparent_size_axis();  ///< d_a/d* over [0, 6]
MapAxis default_d_over_l_axis();       ///< d/l over [0, 1]
MapAxis default_dstar_over_l_axis();   ///< d*/l over [0, 2]

/// InputError unless both axes are ≥ 0 (and within check_axis limits).
WearMap analytic_map_2d(const MapAxis& real_over_critical, const MapAxis& apparent_over_critical);

/// InputError unless d/l lies in [0, 1], d*/l ≥ 0 and C_inter in [1/3, 2/3] (4.49).
WearMap analytic_map_3d(const MapAxis& d_over_l, const MapAxis& dstar_over_l, double c_inter);

}  // namespace wearscale::wear
