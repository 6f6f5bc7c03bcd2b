#include "wearscale/wear/analytic_wear_maps.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/wear/micro_contacts_2d.hpp"
#include "wearscale/wear/two_contacts_3d.hpp"

namespace wearscale::wear {

namespace {
constexpr double inf = std::numeric_limits<double>::infinity();
}

MapAxis default_real_size_axis() { return {"dr_over_dstar", "d_r/d*", 0.0, 3.0, 301}; }
MapAxis default_apparent_size_axis() { return {"da_over_dstar", "d_a/d*", 0.0, 6.0, 301}; }
MapAxis default_d_over_l_axis() { return {"d_over_l", "d/l", 0.0, 1.0, 201}; }
MapAxis default_dstar_over_l_axis() { return {"dstar_over_l", "d*/l", 0.0, 2.0, 201}; }

WearMap analytic_map_2d(const MapAxis& real_over_critical, const MapAxis& apparent_over_critical) {
  check_axis(real_over_critical, 0.0, inf);
  check_axis(apparent_over_critical, 0.0, inf);
  WearMap map;
  map.kind = "analytic2d";
  map.title = "2D wear map of N micro-contacts (thesis Fig. 3.7)";
  map.x = real_over_critical;
  map.y = apparent_over_critical;
  map.region_names = {{-1, "inaccessible"}, {0, "plastic"}, {1, "separated"}, {2, "combined"}};
  const std::size_t n = map.x.n * map.y.n;
  map.region.resize(n);
  MapLayer r_sep{"R_sep", "E_el,Nq / E_ad,sep = d_r/d* (3.24)", std::vector<double>(n)};
  MapLayer r_comb{"R_comb", "E_el,Nq / E_ad,comb = d_r²/(d_a d*) (3.26)", std::vector<double>(n)};
  MapLayer kappa{"kappa", "κ = d_r/d_a (3.28)", std::vector<double>(n)};
  MapLayer kappa_min{"kappa_min", "least κ of a combined particle, √(d*/d_a) (3.29)", std::vector<double>(n)};
  constexpr double d_star = 1.0;  // sizes in units of d*
  for (std::size_t i = 0; i < map.x.n; ++i) {
    const double dr = map.x.value(i);
    for (std::size_t j = 0; j < map.y.n; ++j) {
      const double da = map.y.value(j);
      const std::size_t k = map.index(i, j);
      map.region[k] = static_cast<int>(classify_2d(dr, da, d_star));
      r_sep.values[k] = separated_ratio_2d(dr, d_star);
      r_comb.values[k] = combined_ratio_2d(dr, da, d_star);
      kappa.values[k] = contact_fraction(dr, da);
      kappa_min.values[k] = minimum_contact_fraction(da, d_star);
    }
  }
  map.layers = {std::move(r_sep), std::move(r_comb), std::move(kappa), std::move(kappa_min)};
  return map;
}

WearMap analytic_map_3d(const MapAxis& d_over_l, const MapAxis& dstar_over_l, double c_inter) {
  check_axis(d_over_l, 0.0, 1.0);
  check_axis(dstar_over_l, 0.0, inf);
  constexpr double tol = 1e-12;  // C_inter computed from ν, θ may land a rounding error outside
  if (!(c_inter >= min_interaction_constant - tol && c_inter <= max_interaction_constant + tol))
    throw InputError(fmt::format("3D two-contact wear map: C_inter = {} is not allowed; allowed: 1/3 ≤ C_inter ≤ 2/3 "
                                 "(4.49)", c_inter));
  WearMap map;
  map.kind = "analytic3d";
  map.title = fmt::format("3D wear map of two micro-contacts, C_inter = {:.4g} (thesis Fig. 4.6)", c_inter);
  map.x = d_over_l;
  map.y = dstar_over_l;
  map.region_names = {{0, "plastic"}, {1, "one_separated"}, {2, "two_separated"}, {3, "combined"}};
  map.parameters = {{"C_inter", c_inter}};
  const std::size_t n = map.x.n * map.y.n;
  map.region.resize(n);
  for (const ParticleCase c : particle_cases)
    map.layers.push_back({fmt::format("R_{}", name(c)),
                          fmt::format("energy ratio (4.48) of {}: C_n = {:g}", name(c), count_constant(c)),
                          std::vector<double>(n)});
  for (std::size_t i = 0; i < map.x.n; ++i) {
    const double x = map.x.value(i);
    for (std::size_t j = 0; j < map.y.n; ++j) {
      const double y = map.y.value(j);
      const std::size_t k = map.index(i, j);
      map.region[k] = static_cast<int>(classify_3d(x, y, c_inter));
      for (std::size_t c = 0; c < particle_cases.size(); ++c)
        map.layers[c].values[k] = energy_ratio_3d(particle_cases[c], x, y, c_inter);
    }
  }
  return map;
}

}  // namespace wearscale::wear
