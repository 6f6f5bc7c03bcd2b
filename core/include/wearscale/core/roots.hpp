#pragma once
// Roots of a scalar function on a bracket, with GSL's Brent solver.
#include <functional>
#include <string>

namespace wearscale {

/// The root of f on [lo, hi], where f(lo) and f(hi) differ in sign, to the
/// absolute width `tolerance` (and 1e-13 relative). NumericalError naming
/// `solver` if the bracket is invalid or Brent does not converge in 200 steps.
double find_root(const std::function<double(double)>& f, double lo, double hi, double tolerance,
                 const std::string& solver);

}  // namespace wearscale
