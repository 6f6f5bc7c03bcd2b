#include "wearscale/dem/particles.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>

namespace wearscale::dem {

std::size_t Particles::add(const Sphere& s) {
  position.push_back(s.position);
  velocity.push_back(s.velocity);
  omega.push_back({});
  force.push_back({});
  torque.push_back({});
  radius.push_back(s.radius);
  mass.push_back(0.0);
  inv_mass.push_back(0.0);
  inv_inertia.push_back(0.0);
  id.push_back(next_id_++);
  material.push_back(static_cast<std::uint8_t>(s.material));
  body.push_back(s.body);
  wall.push_back(no_wall);
  image.push_back({0, 0, 0});
  const std::size_t i = size() - 1;
  set_mass(i, s.density * 4.0 / 3.0 * std::numbers::pi * s.radius * s.radius * s.radius);
  return i;
}

void Particles::set_mass(std::size_t i, double m) {
  mass[i] = m;
  inv_mass[i] = 1.0 / m;
  inv_inertia[i] = 1.0 / (0.4 * m * radius[i] * radius[i]);  // solid sphere I = 2mr²/5
}

void Particles::set_density(double density) {
  for (std::size_t i = 0; i < size(); ++i)
    set_mass(i, density * 4.0 / 3.0 * std::numbers::pi * radius[i] * radius[i] * radius[i]);
}

void Particles::reserve(std::size_t n) {
  for_each_array([n](auto& v) { v.reserve(n); });
}

std::size_t Particles::count_mobile() const {
  return static_cast<std::size_t>(std::count(wall.begin(), wall.end(), no_wall));
}

namespace {
template <class T>
void compact(std::vector<T>& v, const std::vector<char>& keep) {
  std::size_t w = 0;
  for (std::size_t r = 0; r < v.size(); ++r)
    if (keep[r]) v[w++] = v[r];
  v.resize(w);
}

template <class T>
void permute(std::vector<T>& v, std::span<const std::size_t> order) {
  std::vector<T> out(v.size());
  for (std::size_t k = 0; k < order.size(); ++k) out[k] = v[order[k]];
  v.swap(out);
}
}  // namespace

void Particles::reorder(std::span<const std::size_t> order) {
  const std::size_t n = size();
  std::vector<char> seen(n, 0);
  bool permutation = order.size() == n;
  for (std::size_t k = 0; k < order.size() && permutation; ++k) {
    permutation = order[k] < n && seen[order[k]] == 0;
    if (permutation) seen[order[k]] = 1;
  }
  if (!permutation) throw std::invalid_argument("Particles::reorder: the order is not a permutation of the particles");
  for_each_array([&](auto& v) { permute(v, order); });
}

void Particles::remove_if(const std::function<bool(std::size_t)>& remove) {
  std::vector<char> keep(size());
  for (std::size_t i = 0; i < size(); ++i) keep[i] = remove(i) ? 0 : 1;
  for_each_array([&](auto& v) { compact(v, keep); });
}

}  // namespace wearscale::dem
