#pragma once
// Small pieces of the DEM pair tests: an open (non-periodic) box and the mass
// of a sphere.
#include <numbers>

#include "wearscale/dem/box.hpp"

namespace wearscale::dem::test_support {

/// A non-periodic cube [-half, half]³ (lengths in the test's units).
inline Box open_box(double half = 200.0) {
  Box b;
  b.lo = {-half, -half, -half};
  b.hi = {half, half, half};
  b.periodic = {false, false, false};
  return b;
}

/// The mass of a sphere of radius r and density rho.
inline double sphere_mass(double r, double rho) { return rho * 4.0 / 3.0 * std::numbers::pi * r * r * r; }

}  // namespace wearscale::dem::test_support
