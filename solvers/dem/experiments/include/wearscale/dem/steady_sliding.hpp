#pragma once
// The steady state the sliding studies report: the means over the second
// half of the slide (the first half carries the running-in), of the samples
// taken while sliding (time > 0).
#include <cstddef>
#include <vector>

namespace wearscale::dem {

struct SteadySliding {
  double tangential_force = 0.0;  ///< mean F_T [N]
  double normal_force = 0.0;      ///< mean F_N [N]
  double friction = 0.0;          ///< mean F_T / mean F_N (0 when F_N is)
  std::size_t samples = 0;        ///< how many samples the means take
};

/// The means over the samples of `history` whose sliding is at least half the
/// last one's (any sample type with time, sliding, tangential_force and normal_force).
template <class Sample>
SteadySliding steady_sliding(const std::vector<Sample>& history) {
  SteadySliding out;
  if (history.empty()) return out;
  double sum_t = 0.0, sum_n = 0.0;
  const double half = 0.5 * history.back().sliding;
  for (const auto& s : history)
    if (s.sliding >= half && s.time > 0.0) {
      sum_t += s.tangential_force;
      sum_n += s.normal_force;
      ++out.samples;
    }
  out.friction = sum_n > 0.0 ? sum_t / sum_n : 0.0;
  if (out.samples > 0) {
    out.tangential_force = sum_t / static_cast<double>(out.samples);
    out.normal_force = sum_n / static_cast<double>(out.samples);
  }
  return out;
}

}  // namespace wearscale::dem
