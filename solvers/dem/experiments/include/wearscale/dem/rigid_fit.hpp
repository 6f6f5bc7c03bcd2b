#pragma once
// The rigid motion that best maps one set of positions onto another (Kabsch:
// SVD of their covariance) and how much of the displacement it leaves
// unexplained: a rolling wear particle moves as a rigid body, a sheared or
// crushed one does not (§6.3, §7.2, §7.3).
#include <array>
#include <cstddef>
#include <vector>

#include "wearscale/dem/vec3.hpp"

namespace wearscale::dem {

class Simulation;
class Engine;

struct RigidFit {
  double residual = 0.0;  ///< RMS misfit of the best rigid motion / RMS displacement about the centroid (0: rigid)
  double angle_y = 0.0;   ///< its rotation about y [rad]
  /// The motion itself: x ↦ rotation (x − from) + to (rotation row-major;
  /// from, to the centroids).
  std::array<double, 9> rotation{1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  Vec3 from{}, to{};
  Vec3 map(const Vec3& x) const {
    const Vec3 d = x - from;
    return Vec3{rotation[0] * d.x + rotation[1] * d.y + rotation[2] * d.z,
                rotation[3] * d.x + rotation[4] * d.y + rotation[5] * d.z,
                rotation[6] * d.x + rotation[7] * d.y + rotation[8] * d.z} +
           to;
  }
};

/// The best rigid motion of positions `a` onto `b` (same particles, same
/// order; unwrapped coordinates).
RigidFit rigid_fit(const std::vector<Vec3>& a, const std::vector<Vec3>& b);

/// The positions of the particles `set` with their periodic images added
/// back (continuous through boundary crossings).
std::vector<Vec3> unwrapped_positions(const Simulation& sim, const std::vector<std::size_t>& set);
std::vector<Vec3> unwrapped_positions(const Engine& engine, const std::vector<std::size_t>& set);

}  // namespace wearscale::dem
