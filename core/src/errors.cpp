#include "wearscale/core/errors.hpp"

#include <fmt/format.h>

namespace wearscale {

InputError InputError::at_key(const std::string& file, const std::string& key,
                              const std::string& value, const std::string& problem,
                              const std::string& allowed) {
  std::string msg = fmt::format("{}: key '{}'", file, key);
  if (!value.empty()) msg += fmt::format(" = {}", value);
  msg += fmt::format(": {}", problem);
  if (!allowed.empty()) msg += fmt::format("; allowed: {}", allowed);
  return InputError(msg);
}

NumericalError::NumericalError(const std::string& solver, long step, const std::string& quantity,
                               const std::string& detail)
    : std::runtime_error(fmt::format("numerical failure in {} at step {}: {}: {}", solver, step,
                                     quantity, detail)),
      solver_(solver),
      step_(step),
      quantity_(quantity),
      detail_(detail) {}

}  // namespace wearscale
