#include "wearscale/core/thread_waiting.hpp"

#include <cstdlib>

#include <fmt/format.h>

namespace wearscale {

std::string thread_waiting() {
  const char* policy = std::getenv("OMP_WAIT_POLICY");
  const char* spins = std::getenv("GOMP_SPINCOUNT");
  if (policy != nullptr) return fmt::format("OMP_WAIT_POLICY={} (set by the user)", policy);
  if (spins != nullptr)
    return fmt::format("spin {} times, then sleep (GOMP_SPINCOUNT={}, set by {})", spins, spins,
                       std::getenv(detail::thread_waiting_marker) != nullptr ? "wearscale" : "the user");
  return "the OpenMP runtime's default (nothing set: this program does not link wearscale::thread_waiting)";
}

}  // namespace wearscale
