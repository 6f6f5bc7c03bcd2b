#include "wearscale/dem/shapes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::dem {

namespace {
Vec3 unit(int axis) {
  if (axis < 0 || axis > 2) throw InputError(fmt::format("DEM shape: axis {}; allowed: 0, 1, 2", axis));
  Vec3 e{};
  e[axis] = 1.0;
  return e;
}

struct Inside {
  const Vec3& x;
  bool operator()(const HalfSpace& h) const { return dot(x - h.point, h.normal) <= 0.0; }
  bool operator()(const Cylinder& c) const {
    const Vec3 axis = c.end - c.start;
    const double length2 = dot(axis, axis);
    const Vec3 rel = x - c.start;
    const double t = dot(rel, axis);  // projection × length
    if (t < 0.0 || t > length2) return false;
    const Vec3 radial = rel - (t / length2) * axis;
    return dot(radial, radial) <= c.radius * c.radius;
  }
  bool operator()(const Ball& b) const {
    const Vec3 d = x - b.center;
    return dot(d, d) <= b.radius * b.radius;
  }
  bool operator()(const Block& b) const {
    return x.x >= b.lo.x && x.x <= b.hi.x && x.y >= b.lo.y && x.y <= b.hi.y && x.z >= b.lo.z && x.z <= b.hi.z;
  }
};

struct Volume {
  double operator()(const HalfSpace&) const { return std::numeric_limits<double>::infinity(); }
  double operator()(const Cylinder& c) const { return std::numbers::pi * c.radius * c.radius * norm(c.end - c.start); }
  double operator()(const Ball& b) const { return 4.0 / 3.0 * std::numbers::pi * b.radius * b.radius * b.radius; }
  double operator()(const Block& b) const {
    const Vec3 l = b.hi - b.lo;
    return std::max(l.x, 0.0) * std::max(l.y, 0.0) * std::max(l.z, 0.0);
  }
};
}  // namespace

HalfSpace below(int axis, double level) {
  const Vec3 e = unit(axis);
  return {level * e, e};
}

HalfSpace above(int axis, double level) {
  const Vec3 e = unit(axis);
  return {level * e, -e};
}

bool contains(const Shape& shape, const Vec3& x) { return std::visit(Inside{x}, shape); }

double volume(const Shape& shape) { return std::visit(Volume{}, shape); }

std::vector<std::size_t> indices_inside(const Particles& p, const Shape& shape) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (contains(shape, p.position[i])) out.push_back(i);
  return out;
}

std::size_t carve(Particles& p, const Shape& shape, Carve mode) {
  const std::size_t before = p.size();
  const bool remove_inside = mode == Carve::remove_inside;
  p.remove_if([&](std::size_t i) { return contains(shape, p.position[i]) == remove_inside; });
  return before - p.size();
}

std::size_t set_body(Particles& p, const Shape& shape, int body) {
  std::size_t tagged = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (contains(shape, p.position[i])) {
      p.body[i] = body;
      ++tagged;
    }
  return tagged;
}

std::pair<double, double> extent(const Particles& p, int axis) {
  unit(axis);
  if (p.empty()) return {0.0, 0.0};
  double lo = p.position[0][axis], hi = lo;
  for (const auto& x : p.position) {
    lo = std::min(lo, x[axis]);
    hi = std::max(hi, x[axis]);
  }
  return {lo, hi};
}

}  // namespace wearscale::dem
