#include "wearscale/coupling/scale.hpp"

#include <algorithm>
#include <stdexcept>

namespace wearscale::coupling {

std::vector<std::string> ScaleRegistry::texts(const std::vector<Key>& keys) {
  std::vector<std::string> out;
  for (const auto& k : keys) out.push_back(k.to_string());
  return out;
}

std::unique_ptr<Scale> ScaleRegistry::checked(std::unique_ptr<Scale> scale, const Ports& ports,
                                              const ScaleSetup& setup) {
  auto check = [&](const std::vector<Key>& keys, const std::vector<Key>& declared, const char* verb) {
    for (const auto& k : keys)
      if (std::none_of(declared.begin(), declared.end(), [&](const Key& d) { return d.what == k.what; }))
        throw std::logic_error(setup.kind + "/" + setup.backend + " " + verb + " " + k.to_string() +
                               ", a quantity its Ports do not declare");
  };
  check(scale->consumes(), ports.consumes, "consumes");
  check(scale->provides(), ports.provides, "provides");
  return scale;
}

}  // namespace wearscale::coupling
