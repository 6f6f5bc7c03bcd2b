#pragma once
// The roughness of a particle surface (§7.2): the box length along x cut into
// bins about d0 wide; in each bin the surface height is the outermost edge of
// the chosen particles (z + r for a surface facing up, z − r facing down);
// Sa is the arithmetic mean deviation of those heights. Bins holding none of
// the chosen particles are left out.
#include <cstddef>
#include <functional>
#include <vector>

#include "wearscale/dem/box.hpp"
#include "wearscale/dem/particles.hpp"

namespace wearscale::dem {

enum class Facing { up, down };

/// Sa = ⟨|h − ⟨h⟩|⟩ of samples (0 if empty).
double arithmetic_roughness(const std::vector<double>& heights);

/// The surface heights per bin along x (bins of width ≈ bin_width covering
/// the box length), from the particles for which chosen(i) is true.
std::vector<double> surface_heights(const Particles& p, const Box& box, const std::function<bool(std::size_t)>& chosen,
                                    Facing facing, double bin_width);

/// Sa of that surface.
double surface_roughness(const Particles& p, const Box& box, const std::function<bool(std::size_t)>& chosen,
                         Facing facing, double bin_width);

}  // namespace wearscale::dem
