#pragma once
// The oxidized asperity of §9.3.3 (Fig. 9.26) reduced for the default test
// set: the thesis' geometry (150 × 150 nm periodic, a 5 nm SiO2 layer on HCP
// Si, a loose SiO2 cylinder of D = 50 nm, a rigid SiO2 plate pressed at
// 100 MPa) with d0 = 6 nm instead of 1.5 nm (about 5 800 particles), the cell
// 95 nm high instead of 75 (at d0 = 6 nm the plate, the clearances and the Si
// wall need the room), slid at 50 m/s (thesis: 10 m/s) after 1 nm of loading.
// The Si/SiO2 pairs take the case's adhesion energy (0.5 J/m²), or with
// `interface_surface_energy` empty mix() of the two materials (1.34 J/m²).
#include <optional>

#include "wearscale/dem/oxide_asperity.hpp"
#include "wearscale/materials/material.hpp"

namespace wearscale::dem::test_support {

inline constexpr double reduced_oxide_d0 = 6e-9;

inline constexpr double case_interface_surface_energy = 0.5;  // J/m², cases/dem_oxide_asperity.toml

inline OxideAsperitySpec reduced_oxide_asperity(
    double sliding_distance, std::optional<double> interface_surface_energy = case_interface_surface_energy) {
  OxideAsperitySpec s;
  s.oxide = cohesive_material(materials::silica(), 0.5);            // Table 6.5
  s.substrate = cohesive_material(materials::silicon(), 0.5, 0.9);  // Table 2.1, η as the case
  s.substrate.poisson = 0.2;  // as the case: pair forces model ν ≤ 1/4
  s.d0 = reduced_oxide_d0;
  s.box = {150e-9, 150e-9, 95e-9};
  s.velocity = 50.0;
  s.sliding_distance = sliding_distance;
  s.settle_distance = 1e-9;
  if (interface_surface_energy) {
    s.interface = mix(s.oxide, s.substrate);
    s.interface->surface_energy = *interface_surface_energy;
  }
  return s;
}

}  // namespace wearscale::dem::test_support
