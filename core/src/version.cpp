#include "wearscale/core/version.hpp"

namespace wearscale {

std::string version() { return WEARSCALE_VERSION; }

}  // namespace wearscale
