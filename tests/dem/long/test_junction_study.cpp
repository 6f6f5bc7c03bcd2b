// The junction study of §7.1.1 at the thesis' cell (d0 = 1.5 nm, L = 37.5 nm,
// 36.4 nm high; 4.9 nm deep instead of 2.4, see junction_strength.hpp), slid
// over one L at 50 m/s instead of 10 (the peaks agree within 5 %: 3.10 against
// 3.11 GPa for D = 20 nm, 1.27 against 1.33 GPa for D = 10 nm). About 3-5 min.
#include <gtest/gtest.h>

#include "wearscale/dem/junction_strength.hpp"
#include "wearscale/materials/material.hpp"

using namespace wearscale;
using namespace wearscale::dem;

namespace {
JunctionStrengthResult thesis_cell(double diameter, double pressure) {
  JunctionStrengthSpec s;
  s.top = s.bottom = cohesive_material(materials::silica(), 0.5);
  s.cell.d0 = 1.5e-9;
  s.cell.length = 25;
  s.cell.height = 14;
  s.contact_ratio = diameter / 37.5e-9;
  s.pressure = pressure;
  s.velocity = 50.0;
  return run_junction_strength(s);
}
}  // namespace

// Fig. 7.2 at p_N = 0.5 GPa: D = 20 nm (above d* ≈ 18 nm) detaches into a
// rolling particle; its peak resistance is about proportional to D, twice
// that of D = 10 nm; both lie above p_T = p_N and below the model (7.9) with
// σ_m,T = 9 GPa ("the model predicts resistances overall higher than DEM").
// Measured: 3.10 GPa (A/A0 0.56, rolling rate 0.92, misfit 0.09) and
// 1.27 GPa (A/A0 0.24).
TEST(JunctionStudy, ThesisCellLargerJunctionsDetachAndResistMore) {
  const double p_n = 0.5e9, sigma = materials::silica().shear_strength;
  const auto large = thesis_cell(20e-9, p_n);
  const auto small = thesis_cell(10e-9, p_n);
  EXPECT_EQ(large.verdict(), "detached") << "rolling " << large.rolling_rate << " misfit " << large.rigid_residual;
  EXPECT_NEAR(large.rolling_rate, 1.0, 0.3);
  EXPECT_GT(large.peak_tangential, 1.8 * small.peak_tangential);
  for (const auto* r : {&large, &small}) {
    EXPECT_GE(r->peak_tangential, p_n);
    EXPECT_LT(r->peak_tangential, r->initial_contact_ratio * sigma);
  }
  // Proportional to the size: the same σ within 15 % (measured 5.5 GPa both).
  EXPECT_NEAR(large.peak_tangential / large.initial_contact_ratio, small.peak_tangential / small.initial_contact_ratio,
              0.15 * large.peak_tangential / large.initial_contact_ratio);
}
