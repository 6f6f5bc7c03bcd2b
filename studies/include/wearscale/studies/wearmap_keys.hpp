#pragma once
// The keys of the wear-map studies' tables [wearmap.analytic2d],
// [wearmap.analytic3d] and [wearmap.rough], each declared once in a key table
// beside the struct it fills (the tables are in the studies' files). The
// defaults are the members' initializers: the Python bindings take theirs
// from these structs.
#include <cstddef>
#include <string>
#include <utility>

#include "wearscale/io/key_table.hpp"
#include "wearscale/wear/analytic_wear_maps.hpp"
#include "wearscale/wear/rough_wear_map.hpp"

namespace wearscale::studies {

/// [wearmap.analytic2d]: the ranges of d_r/d* and d_a/d* (Fig. 3.7) and the points along each.
struct WearmapAnalytic2dKeys {
  std::pair<double, double> dr_over_dstar{wear::default_real_size_axis().min, wear::default_real_size_axis().max};
  std::pair<double, double> da_over_dstar{wear::default_apparent_size_axis().min,
                                          wear::default_apparent_size_axis().max};
  std::size_t n = wear::default_real_size_axis().n;
};
const KeyTable<WearmapAnalytic2dKeys>& wearmap_analytic2d_keys();

/// [wearmap.analytic3d]: the ranges of d/l and d*/l (Fig. 4.6), the points
/// along each, and the interaction constant's ν and θ (4.49), or the bound
/// `interaction` names ("max", "min"; "": none, ν and θ as given).
struct WearmapAnalytic3dKeys {
  std::pair<double, double> d_over_l{wear::default_d_over_l_axis().min, wear::default_d_over_l_axis().max};
  std::pair<double, double> dstar_over_l{wear::default_dstar_over_l_axis().min,
                                         wear::default_dstar_over_l_axis().max};
  std::size_t n = wear::default_d_over_l_axis().n;
  std::string interaction;
  double nu = 0.5;
  double theta = 0.0;
};
const KeyTable<WearmapAnalytic3dKeys>& wearmap_analytic3d_keys();

/// [wearmap.rough]: the surfaces, the (p̃_N, d*/L) grid and the detachment
/// model of the rough wear maps (ch. 5); `map` holds what wear::RoughWearMapSpec
/// takes (its seeds, loads and critical diameters are made from the counts and ranges).
struct WearmapRoughKeys {
  wear::RoughWearMapSpec map;
  std::size_t seeds = 5;
  std::pair<double, double> loads{0.01, 0.3};
  std::size_t n_loads = 20;
  std::pair<double, double> dstar_over_l{0.01, 0.2};
  std::size_t n_dstar = 20;
  std::size_t naive_pixels = 0;
  std::size_t naive_max_solves = 0;
};
const KeyTable<WearmapRoughKeys>& wearmap_rough_keys();

}  // namespace wearscale::studies
