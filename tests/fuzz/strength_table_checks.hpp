#pragma once
// What the strength-table harnesses assert about what they read: a table
// that passes the writer's own check, whose law evaluates to finite,
// non-negative strengths over its pressure range. A violation aborts.
#include <cmath>
#include <cstdlib>
#include <utility>

#include "wearscale/materials/strength_law.hpp"
#include "wearscale/materials/strength_table.hpp"

namespace fuzz {

/// Aborts unless `table` is valid and its law finite and non-negative.
inline void check_strength_table(wearscale::materials::StrengthTable table) {
  wearscale::materials::validate(table);
  const wearscale::materials::StrengthLaw law(std::move(table));
  const double lo = law.min_pressure(), hi = law.max_pressure();
  for (int k = 0; k <= 16; ++k) {
    const double p = lo + (hi - lo) * k / 16.0;
    const double a = law.sigma_max(p), d = law.sigma_dyn(p);
    if (!std::isfinite(a) || !std::isfinite(d) || a < 0.0 || d < 0.0) std::abort();
  }
}

}  // namespace fuzz
