#include "wearscale/dem/virial_stress.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wearscale::dem {

namespace {
template <class Indices>
SymTensor stress_of(const Particles& p, const std::vector<SymTensor>& w, const Indices& region, std::size_t count,
                    double volume) {
  if (w.size() != p.size())
    throw std::logic_error(
        "virial stress: the simulation keeps no per-particle virial for its particles; call "
        "set_track_virial(true) and compute_forces() (or step()) first");
  if (!(volume > 0.0)) throw std::invalid_argument("virial stress: the region's volume must be > 0");
  SymTensor s{};
  if (count == 0) return s;
  // v̄: the streaming velocity, which carries no stress.
  Vec3 momentum{};
  double mass = 0.0;
  for (std::size_t i : region) {
    momentum += p.mass[i] * p.velocity[i];
    mass += p.mass[i];
  }
  const Vec3 mean = (1.0 / mass) * momentum;
  for (std::size_t i : region) {
    const Vec3 u = p.velocity[i] - mean;
    const double m = p.mass[i];
    s[0] += w[i][0] - m * u.x * u.x;
    s[1] += w[i][1] - m * u.y * u.y;
    s[2] += w[i][2] - m * u.z * u.z;
    s[3] += w[i][3] - m * u.x * u.y;
    s[4] += w[i][4] - m * u.x * u.z;
    s[5] += w[i][5] - m * u.y * u.z;
  }
  for (double& c : s) c /= volume;
  return s;
}

struct AllIndices {
  std::size_t n;
  struct Iterator {
    std::size_t i;
    std::size_t operator*() const { return i; }
    Iterator& operator++() {
      ++i;
      return *this;
    }
    bool operator!=(const Iterator& o) const { return i != o.i; }
  };
  Iterator begin() const { return {0}; }
  Iterator end() const { return {n}; }
};

template <class System>
SymTensor region_stress(const System& sim, std::span<const std::size_t> region, double volume) {
  for (std::size_t i : region)
    if (i >= sim.particles().size()) throw std::out_of_range("virial stress: particle index out of range");
  return stress_of(sim.particles(), sim.virial(), region, region.size(), volume);
}

template <class System>
SymTensor whole_box_stress(const System& sim) {
  const std::size_t n = sim.particles().size();
  return stress_of(sim.particles(), sim.virial(), AllIndices{n}, n, sim.box().volume());
}
}  // namespace

SymTensor virial_stress(const Simulation& sim, std::span<const std::size_t> region, double volume) {
  return region_stress(sim, region, volume);
}
SymTensor virial_stress(const Engine& engine, std::span<const std::size_t> region, double volume) {
  return region_stress(engine, region, volume);
}
SymTensor box_stress(const Simulation& sim) { return whole_box_stress(sim); }
SymTensor box_stress(const Engine& engine) { return whole_box_stress(engine); }

double max_normal_stress(const SymTensor& s) {
  return std::max({std::fabs(s[0]), std::fabs(s[1]), std::fabs(s[2])});
}

double max_stress(const SymTensor& s) {
  double m = 0.0;
  for (double c : s) m = std::max(m, std::fabs(c));
  return m;
}

}  // namespace wearscale::dem
