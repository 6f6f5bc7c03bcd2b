#pragma once
// The junction cell of §7.1.1 (Fig. 7.2): SiO2 (Table 6.5, s = ½) on an HCP
// lattice of d0 = 1.5 nm, 25 × 14 double rows × one HCP cell (37.5 × 36.4 ×
// 2.45 nm³, the thesis' 2.4 nm), one junction of diameter D under p_N.
#include "wearscale/dem/junction_strength.hpp"
#include "wearscale/materials/material.hpp"

namespace wearscale::dem::test_support {

inline constexpr double thesis_cell_length = 37.5e-9;

inline JunctionStrengthSpec thesis_junction_cell(double diameter, double pressure, double velocity) {
  JunctionStrengthSpec s;
  s.top = s.bottom = cohesive_material(materials::silica(), 0.5);
  s.cell.d0 = 1.5e-9;
  s.cell.length = 25;
  s.cell.height = 14;
  s.cell.depth = 1;
  s.contact_ratio = diameter / thesis_cell_length;
  s.pressure = pressure;
  s.velocity = velocity;
  return s;
}

}  // namespace wearscale::dem::test_support
