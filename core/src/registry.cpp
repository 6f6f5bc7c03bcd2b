#include "wearscale/core/registry.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/edit_distance.hpp"

namespace wearscale {

std::string closest_name(const std::vector<std::string>& known, const std::string& name) {
  std::string best;
  std::size_t best_d = 3;  // at most two edits
  for (const auto& n : known)
    if (const auto d = edit_distance(n, name); d < best_d) best_d = d, best = n;
  return best;
}

std::string BackendInfo::unknown(const std::string& kind, const std::string& name,
                                 const std::vector<std::string>& kinds, const std::vector<std::string>& known) {
  if (known.empty()) return fmt::format("unknown scale kind '{}'; known kinds: {}", kind, fmt::join(kinds, ", "));
  return fmt::format("unknown {} backend '{}'; known {} backends: {}", kind, name, kind, fmt::join(known, ", "));
}

}  // namespace wearscale
