#include "wearscale/core/checkpoint_state.hpp"

#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale {

void CheckpointState::put(const std::string& name, std::span<const double> values) {
  arrays_[name].assign(values.begin(), values.end());
}
void CheckpointState::put(const std::string& name, double value) { arrays_[name] = {value}; }
void CheckpointState::put_text(const std::string& name, std::string text) { texts_[name] = std::move(text); }

bool CheckpointState::has(const std::string& name) const {
  return arrays_.count(name) != 0 || texts_.count(name) != 0;
}

const std::vector<double>& CheckpointState::array(const std::string& name) const {
  const auto it = arrays_.find(name);
  if (it == arrays_.end())
    throw InputError(fmt::format("{}: no entry '{}' (written by another version of wearscale?)", origin, name));
  return it->second;
}

double CheckpointState::scalar(const std::string& name) const {
  const auto& a = array(name);
  if (a.size() != 1) throw InputError(fmt::format("{}: entry '{}' holds {} values, expected one", origin, name, a.size()));
  return a[0];
}

long CheckpointState::count(const std::string& name, double low, double high) const {
  const double v = scalar(name);
  if (const std::string problem = count_problem(name, v, low, high); !problem.empty())
    throw InputError(fmt::format("{}: no state a run reaches ({}); the checkpoint was changed or written by another "
                                 "program: delete it to start afresh",
                                 origin, problem));
  return static_cast<long>(v);
}

std::string count_problem(const std::string& name, double value, double low, double high) {
  if (std::isfinite(value) && value >= low && value <= high && value == std::floor(value)) return {};
  return fmt::format("{} = {:g}; allowed: a whole number within [{:g}, {:g}]", name, value, low, high);
}

const std::string& CheckpointState::text(const std::string& name) const {
  const auto it = texts_.find(name);
  if (it == texts_.end())
    throw InputError(fmt::format("{}: no entry '{}' (written by another version of wearscale?)", origin, name));
  return it->second;
}

}  // namespace wearscale
