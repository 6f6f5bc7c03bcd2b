#include "wearscale/core/checkpoint_state.hpp"

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

const std::string& CheckpointState::text(const std::string& name) const {
  const auto it = texts_.find(name);
  if (it == texts_.end())
    throw InputError(fmt::format("{}: no entry '{}' (written by another version of wearscale?)", origin, name));
  return it->second;
}

}  // namespace wearscale
