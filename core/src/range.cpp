#include "wearscale/core/range.hpp"

#include <cmath>

#include <fmt/format.h>

namespace wearscale {

bool Range::contains(double v) const {
  if (std::isnan(v)) return false;
  if (std::isinf(v)) return infinity_ok && v > 0;
  if (lo_open ? !(v > lo) : !(v >= lo)) return false;
  if (hi_open ? !(v < hi) : !(v <= hi)) return false;
  return true;
}

double Range::snap(double v) const {
  const double tolerance = 4.0 * std::numeric_limits<double>::epsilon();
  auto near = [&](double bound) { return std::isfinite(bound) && std::fabs(v - bound) <= tolerance * std::fabs(bound); };
  if (!lo_open && near(lo)) return lo;
  if (!hi_open && near(hi)) return hi;
  return v;
}

std::string Range::describe() const {
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  std::string s;
  if (has_lo && has_hi)
    s = fmt::format("{}{:g}, {:g}{}", lo_open ? "(" : "[", lo, hi, hi_open ? ")" : "]");
  else if (has_lo)
    s = fmt::format("{} {:g}", lo_open ? ">" : "≥", lo);
  else if (has_hi)
    s = fmt::format("{} {:g}", hi_open ? "<" : "≤", hi);
  else
    s = "any finite number";
  if (infinity_ok) s += " or inf";
  return s;
}

}  // namespace wearscale
