#pragma once
// The particles of a DEM system, stored as parallel arrays (one entry per
// sphere): the state velocity Verlet integrates and the tags measurements use.
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "wearscale/dem/vec3.hpp"

namespace wearscale::dem {

/// Marks a particle that belongs to no wall (it is integrated).
inline constexpr std::int16_t no_wall = -1;

/// One sphere to add: geometry, mass from the density, and tags.
struct Sphere {
  Vec3 position{};
  double radius = 0.0;
  double density = 0.0;
  Vec3 velocity{};
  int material = 0;  ///< index into the force law's material table
  int body = 0;      ///< body tag (which solid the particle belongs to)
};

class Particles {
 public:
  std::size_t size() const { return radius.size(); }
  bool empty() const { return radius.empty(); }

  /// Appends a sphere; m = ρ 4π r³/3, I = 2 m r²/5. Returns its index.
  std::size_t add(const Sphere& s);
  /// Removes every particle for which `remove(i)` is true, keeping the order
  /// of the others (a neighbour list built before is invalid afterwards).
  void remove_if(const std::function<bool(std::size_t)>& remove);
  /// Renumbers the particles: the one at order[k] becomes particle k, every
  /// array alike (ids, tags and state travel with their particle). `order`
  /// must be a permutation of 0 … size()−1 (std::invalid_argument otherwise).
  void reorder(std::span<const std::size_t> order);
  /// Sets the density of every particle (masses and inertias follow).
  void set_density(double density);
  /// Mass and moment of inertia from radius and density, for particle i.
  void set_mass(std::size_t i, double mass);
  void reserve(std::size_t n);

  bool frozen(std::size_t i) const { return wall[i] != no_wall; }
  std::size_t count_mobile() const;

  // State integrated by velocity Verlet (6.1).
  std::vector<Vec3> position, velocity, omega, force, torque;
  // Properties.
  std::vector<double> radius, mass, inv_mass, inv_inertia;
  // Tags.
  std::vector<std::int64_t> id;           ///< stable identity (output, history)
  std::vector<std::uint8_t> material;     ///< index into the material table
  std::vector<std::int32_t> body;         ///< body tag
  std::vector<std::int16_t> wall;         ///< wall index or no_wall
  std::vector<std::array<std::int32_t, 3>> image;  ///< periodic images crossed

  /// Calls f on every per-particle array: what moves, drops or sizes particles
  /// (reorder, remove_if, reserve, a restored state) treats them all alike,
  /// named once here.
  template <class F>
  void for_each_array(F&& f) {
    f(position), f(velocity), f(omega), f(force), f(torque);
    f(radius), f(mass), f(inv_mass), f(inv_inertia);
    f(id), f(material), f(body), f(wall), f(image);
  }

 private:
  std::int64_t next_id_ = 1;
};

}  // namespace wearscale::dem
