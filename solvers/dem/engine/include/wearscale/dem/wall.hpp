#pragma once
// A rigid wall made of frozen particles: held fixed, moved at a velocity, or
// loaded with a pressure along one axis (its motion along that axis then
// integrated from the net force on it).
#include <cstddef>
#include <vector>

#include "wearscale/dem/vec3.hpp"

namespace wearscale::dem {

struct WallMotion {
  enum class Kind { Fixed, Velocity, Pressure };
  Kind kind = Kind::Fixed;
  /// Imposed velocity (Velocity), or the velocity across the load axis
  /// (Pressure; its component along the axis is ignored).
  Vec3 velocity{};
  // Pressure control.
  int axis = 2;            ///< load axis 0, 1, 2
  double pressure = 0.0;   ///< p > 0 pushes the wall into the sample
  double area = 0.0;       ///< loaded area A: the load is p A
  int outward = +1;        ///< +1: the sample lies on the low side of the wall
  double mass = 0.0;       ///< 0: the sum of its particles' masses
  double damping = 0.0;    ///< viscous damping of the wall's motion [force/velocity]

  static WallMotion fixed() { return {}; }
  static WallMotion moving(Vec3 v) {
    WallMotion w;
    w.kind = Kind::Velocity;
    w.velocity = v;
    return w;
  }
  static WallMotion pressed(int axis, double pressure, double area, int outward, Vec3 lateral = {}) {
    WallMotion w;
    w.kind = Kind::Pressure;
    w.axis = axis;
    w.pressure = pressure;
    w.area = area;
    w.outward = outward;
    w.velocity = lateral;
    return w;
  }
};

/// A wall's state: its particles, motion law, and what acts on it.
struct Wall {
  std::vector<std::size_t> members;
  WallMotion motion;
  double mass = 0.0;     ///< inertia along the load axis (Pressure)
  Vec3 velocity{};       ///< current velocity of all its particles
  Vec3 force{};          ///< net force of the sample on the wall (last step)
  Vec3 displacement{};   ///< total displacement since it was made
};

}  // namespace wearscale::dem
