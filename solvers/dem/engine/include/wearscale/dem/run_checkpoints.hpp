#pragma once
// How a long DEM driver is checkpointed and resumed. The driver offers its
// state after every sample: `at_sample(step, make)`, where make() gives the
// DEM system and everything measured so far (the caller decides whether to
// save it, e.g. a Checkpointer's policy). A driver started `from` such a state
// sets its system up as before (the set-up is deterministic), restores the
// state and continues where it stopped: the same result bit for bit with the
// same thread count.
#include <cstring>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include "wearscale/core/checkpoint_state.hpp"
#include "wearscale/dem/vec3.hpp"

namespace wearscale::dem {

struct RunCheckpoints {
  std::function<void(long step, const std::function<CheckpointState()>& make)> at_sample;
  const CheckpointState* from = nullptr;

  /// Offers the state after `step` (no-op without at_sample).
  void offer(long step, const std::function<CheckpointState()>& make) const {
    if (at_sample) at_sample(step, make);
  }
};

// What drivers save beside the DEM system: points, particle indices and
// histories of samples (structs of doubles), bit for bit. The readers throw
// InputError naming the entry when it does not hold what they expect.
void put_points(CheckpointState& st, const std::string& name, const std::vector<Vec3>& points);
std::vector<Vec3> points(const CheckpointState& st, const std::string& name);
void put_indices(CheckpointState& st, const std::string& name, const std::vector<std::size_t>& indices);
std::vector<std::size_t> indices(const CheckpointState& st, const std::string& name);
/// The entry must hold `count` values (else InputError: not this run's state).
const std::vector<double>& tallies(const CheckpointState& st, const std::string& name, std::size_t count);

template <class Sample>
void put_samples(CheckpointState& st, const std::string& name, const std::vector<Sample>& samples) {
  static_assert(std::is_standard_layout_v<Sample> && std::is_trivially_copyable_v<Sample> &&
                    sizeof(Sample) % sizeof(double) == 0,
                "a sample is a struct of doubles");
  std::vector<double> flat(samples.size() * (sizeof(Sample) / sizeof(double)));
  if (!flat.empty()) std::memcpy(flat.data(), samples.data(), flat.size() * sizeof(double));
  st.put(name, flat);
}

/// The most steps a DEM run may plan: 10^10 (years of one core at the
/// thesis' sizes). A distance or time asked for in steps beyond it (a sliding
/// distance of 1e300 m, a time step of 1e-300 Δt_c) is bad input, refused
/// before the run, never a loop that does not end.
inline constexpr double max_planned_steps = 1e10;

/// `steps` (a distance over a step length, rounded up) as a count: InputError naming `what` unless it is
/// finite and at most max_planned_steps.
long planned_steps(double steps, const std::string& what);

/// A step count kept among a checkpoint's tallies: a whole number ≥ 0, checked
/// before it becomes an integer (a NaN or 1e300 step would never end a loop);
/// InputError naming the entry otherwise.
long step_tally(const CheckpointState& st, const std::string& name, double value);

/// InputError naming the entry if its length is not a whole number of samples.
void require_whole(const CheckpointState& st, const std::string& name, std::size_t size, std::size_t per_sample);

template <class Sample>
std::vector<Sample> samples(const CheckpointState& st, const std::string& name) {
  constexpr std::size_t per = sizeof(Sample) / sizeof(double);
  const auto& flat = st.array(name);
  require_whole(st, name, flat.size(), per);
  std::vector<Sample> out(flat.size() / per);
  if (!out.empty()) std::memcpy(static_cast<void*>(out.data()), flat.data(), flat.size() * sizeof(double));
  return out;
}

}  // namespace wearscale::dem
