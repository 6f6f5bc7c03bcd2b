#include "wearscale/core/grid.hpp"

#include <fmt/format.h>

namespace wearscale {

std::string Grid2D::to_string() const { return fmt::format("{}×{} points over {:g}×{:g} m", nx, ny, lx, ly); }

}  // namespace wearscale
