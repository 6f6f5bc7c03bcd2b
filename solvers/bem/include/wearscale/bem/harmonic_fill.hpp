#pragma once
// Filling the missing points of a measured topography by harmonic (Laplace)
// interpolation: the filled heights solve the discrete Laplace equation
// ∇²h = 0 (5-point stencil, weights 1/dx² and 1/dy²) with the measured
// heights around them as boundary values and no flux across the edge of
// the data (a measurement is not periodic). A plane, and any discrete
// harmonic function, is filled exactly.
#include <cstdint>
#include <span>

#include "wearscale/core/field.hpp"

namespace wearscale::bem {

/// Fills the points of `h` where `missing` is non-zero (one flag per point,
/// wearscale's order). Returns the number filled. std::invalid_argument if
/// the sizes differ or no point is measured; NumericalError if the sparse
/// solve fails.
std::size_t harmonic_fill(RealField& h, std::span<const std::uint8_t> missing);

}  // namespace wearscale::bem
