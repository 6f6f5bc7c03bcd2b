#include "wearscale/tribometer/friction_average.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::tribometer {

FrictionAverage::FrictionAverage(std::vector<double> s, std::vector<double> integral)
    : s_(std::move(s)), integral_(std::move(integral)) {
  if (s_.empty() || s_.size() != integral_.size())
    throw InputError(fmt::format("friction average: {} distances for {} integrals", s_.size(), integral_.size()));
  for (std::size_t k = 1; k < s_.size(); ++k)
    if (!(s_[k] >= s_[k - 1]))
      throw InputError(fmt::format("friction average: the distance decreases at sample {} ({:g} after {:g} m)", k,
                                   s_[k], s_[k - 1]));
}

double FrictionAverage::integral_at(double s) const {
  if (s <= s_.front()) return integral_.front();
  if (s >= s_.back()) return integral_.back();
  const auto hi = static_cast<std::size_t>(std::upper_bound(s_.begin(), s_.end(), s) - s_.begin());
  const std::size_t lo = hi - 1;
  const double span = s_[hi] - s_[lo];
  const double f = span > 0.0 ? (s - s_[lo]) / span : 1.0;
  return integral_[lo] + f * (integral_[hi] - integral_[lo]);
}

double FrictionAverage::mean(double a, double b) const {
  a = std::max(a, s_.front());
  b = std::min(b, s_.back());
  if (!(b > a)) throw InputError(fmt::format("friction average: an empty stretch [{:g}, {:g}] m", a, b));
  return (integral_at(b) - integral_at(a)) / (b - a);
}

std::vector<double> FrictionAverage::centred_moving_average(double length) const {
  std::vector<double> out(s_.size());
  if (!(s_.back() > s_.front())) {  // a single point: its μ is not known from the integral alone
    std::fill(out.begin(), out.end(), std::nan(""));
    return out;
  }
  for (std::size_t k = 0; k < s_.size(); ++k) {
    double a = s_[k] - 0.5 * length, b = s_[k] + 0.5 * length;
    a = std::max(a, s_.front());
    b = std::min(b, s_.back());
    out[k] = b > a ? (integral_at(b) - integral_at(a)) / (b - a) : std::nan("");
  }
  return out;
}

namespace {
FrictionWindow window(double start, double end, double period, bool last) {
  const double total = end - start;
  if (period > 0.0) {
    if (total <= period)
      return {start, end, fmt::format("the whole run (shorter than one tilt period, {:g} m)", period)};
    return last ? FrictionWindow{end - period, end, fmt::format("the last whole tilt period ({:g} m)", period)}
                : FrictionWindow{start, start + period, fmt::format("the first tilt period ({:g} m)", period)};
  }
  return last ? FrictionWindow{end - 0.05 * total, end, "the last 5 % of the sliding distance"}
              : FrictionWindow{start, start + 0.05 * total, "the first 5 % of the sliding distance"};
}
}  // namespace

FrictionWindow final_window(double start, double end, double tilt_period) {
  return window(start, end, tilt_period, true);
}
FrictionWindow initial_window(double start, double end, double tilt_period) {
  return window(start, end, tilt_period, false);
}

}  // namespace wearscale::tribometer
