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

long planned_steps(double steps, const std::string& what) {
  if (!(std::isfinite(steps) && steps >= 0.0 && steps <= max_planned_steps))
    throw InputError(fmt::format("{} asks for {:.3g} steps; allowed: at most {:g} (check the distance, velocity and "
                                 "time step)",
                                 what, steps, max_planned_steps));
  return static_cast<long>(std::ceil(steps));
}

long step_tally(const CheckpointState& st, const std::string& name, double value) {
  if (const std::string problem = count_problem(name + " (steps)", value, 0.0, 9e15); !problem.empty())
    throw InputError(fmt::format("{}: no state a run reaches ({}); the checkpoint was changed or written by another "
                                 "program: delete it to start afresh",
                                 st.origin, problem));
  return static_cast<long>(value);
}

std::vector<Vec3> points(const CheckpointState& st, const std::string& name) {
  const auto& flat = st.array(name);
  require_whole(st, name, flat.size(), 3);
  for (const double v : flat)
    if (!std::isfinite(v))
      throw InputError(fmt::format("{}: entry '{}' holds {}, not a position: not the state of this run", st.origin,
                                   name, v));
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
