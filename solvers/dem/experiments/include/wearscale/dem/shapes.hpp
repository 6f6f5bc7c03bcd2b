#pragma once
// Regions of space for carving a sample into bodies (§6.3: two surfaces and a
// cylindrical junction cut from a relaxed amorphous box), tagging bodies and
// picking wall layers. A particle belongs to a region when its centre does.
#include <cstddef>
#include <utility>
#include <variant>
#include <vector>

#include "wearscale/dem/particles.hpp"
#include "wearscale/dem/vec3.hpp"

namespace wearscale::dem {

/// The solid on one side of a plane: points x with (x − point)·normal ≤ 0
/// (`normal` is the outward normal of its surface; any length > 0).
struct HalfSpace {
  Vec3 point{};
  Vec3 normal{0.0, 0.0, 1.0};
};

/// A finite circular cylinder: points within `radius` of the segment from
/// `start` to `end` whose projection falls on the segment.
struct Cylinder {
  Vec3 start{};
  Vec3 end{0.0, 0.0, 1.0};
  double radius = 1.0;
};

/// A ball: points within `radius` of `center`.
struct Ball {
  Vec3 center{};
  double radius = 1.0;
};

/// An axis-aligned block [lo, hi] (closed).
struct Block {
  Vec3 lo{};
  Vec3 hi{};
};

using Shape = std::variant<HalfSpace, Cylinder, Ball, Block>;

/// Points with coordinate `axis` ≤ level, and ≥ level.
HalfSpace below(int axis, double level);
HalfSpace above(int axis, double level);

/// Whether the point lies in the shape (boundary included).
bool contains(const Shape& shape, const Vec3& x);
/// The shape's volume (infinite for a half-space).
double volume(const Shape& shape);

/// The particles whose centres lie in the shape, in increasing index.
std::vector<std::size_t> indices_inside(const Particles& p, const Shape& shape);

enum class Carve { keep_inside, remove_inside };
/// Removes the particles outside (keep_inside) or inside (remove_inside) the
/// shape, keeping the order of the others; returns how many were removed.
std::size_t carve(Particles& p, const Shape& shape, Carve mode);

/// Tags the particles inside the shape with body `body`; returns how many.
std::size_t set_body(Particles& p, const Shape& shape, int body);

/// The lowest and highest centre coordinate along `axis` ({0, 0} if empty),
/// e.g. to pick a wall layer: indices_inside(p, above(2, extent(p, 2).second − 1.5 d0)).
std::pair<double, double> extent(const Particles& p, int axis);

}  // namespace wearscale::dem
