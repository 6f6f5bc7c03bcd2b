#pragma once
// An allowed interval for a numeric input, described in words for errors.
#include <limits>
#include <string>

namespace wearscale {

struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false, hi_open = false;
  bool infinity_ok = false;  ///< accept +inf (e.g. "bulk" layer thickness)

  static Range any() { return {}; }
  static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
  static Range non_negative() { return {0.0, std::numeric_limits<double>::infinity(), false, false}; }
  static Range at_least(double a) { return {a, std::numeric_limits<double>::infinity(), false, false}; }
  static Range greater_than(double a) { return {a, std::numeric_limits<double>::infinity(), true, false}; }
  static Range at_most(double b) { return {-std::numeric_limits<double>::infinity(), b, false, false}; }
  static Range closed(double a, double b) { return {a, b, false, false}; }
  static Range open(double a, double b) { return {a, b, true, true}; }
  static Range closed_open(double a, double b) { return {a, b, false, true}; }
  static Range open_closed(double a, double b) { return {a, b, true, false}; }
  Range or_infinite() const { Range r = *this; r.infinity_ok = true; return r; }

  bool contains(double v) const;
  /// `v`, or a closed finite bound if `v` is within 4 ulps (relative) of it:
  /// bounds are often products of other inputs (3 d0) that round just above
  /// the value a user types (18 nm), which must then be accepted, as the bound.
  double snap(double v) const;
  /// "> 0", "[0, 0.5)", "≥ 2 or inf", "any finite number".
  std::string describe() const;
};

}  // namespace wearscale
