#include "wearscale/dem/run_checkpoints.hpp"

#include <cmath>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::dem {

void require_whole(const CheckpointState& st, const std::string& name, std::size_t size, std::size_t per_sample) {
  if (size % per_sample != 0)
    throw InputError(fmt::format("{}: entry '{}' holds {} values, not a multiple of {}: not the state of this run",
                                 st.origin, name, size, per_sample));
}

void put_points(CheckpointState& st, const std::string& name, const std::vector<Vec3>& points) {
  std::vector<double> flat;
  flat.reserve(3 * points.size());
  for (const Vec3& x : points) flat.insert(flat.end(), {x.x, x.y, x.z});
  st.put(name, flat);
}

std::vector<Vec3> points(const CheckpointState& st, const std::string& name) {
  const auto& flat = st.array(name);
  require_whole(st, name, flat.size(), 3);
  std::vector<Vec3> out;
  out.reserve(flat.size() / 3);
  for (std::size_t k = 0; k < flat.size(); k += 3) out.push_back({flat[k], flat[k + 1], flat[k + 2]});
  return out;
}

void put_indices(CheckpointState& st, const std::string& name, const std::vector<std::size_t>& indices) {
  st.put(name, std::vector<double>(indices.begin(), indices.end()));
}

std::vector<std::size_t> indices(const CheckpointState& st, const std::string& name) {
  std::vector<std::size_t> out;
  for (double v : st.array(name)) {
    if (!(v >= 0.0) || v != std::floor(v))
      throw InputError(fmt::format("{}: entry '{}' holds {}, not a particle index: not the state of this run",
                                   st.origin, name, v));
    out.push_back(static_cast<std::size_t>(v));
  }
  return out;
}

const std::vector<double>& tallies(const CheckpointState& st, const std::string& name, std::size_t count) {
  const auto& t = st.array(name);
  if (t.size() != count)
    throw InputError(fmt::format("{}: entry '{}' holds {} values, expected {}: not the state of this run", st.origin,
                                 name, t.size(), count));
  return t;
}

}  // namespace wearscale::dem
