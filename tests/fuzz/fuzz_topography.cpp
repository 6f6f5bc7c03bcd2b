// Fuzzes the text topography reader: any bytes give a finite height grid of
// the size the text says, or InputError naming the problem.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "wearscale/bem/topography_io.hpp"
#include "wearscale/core/errors.hpp"

using namespace wearscale;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  // First byte: whether the caller gives the size (as `contact --set contact.size=…` does).
  bem::TopographySize given;
  if (data[0] & 1) given.lx = given.ly = 1e-3;
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    const RealField h = bem::parse_topography_text(text, "fuzz.txt", given);
    const Grid2D& g = h.grid();
    if (g.nx == 0 || g.ny == 0 || h.size() != g.nx * g.ny || !(g.lx > 0.0) || !(g.ly > 0.0) || !std::isfinite(g.lx) ||
        !std::isfinite(g.ly))
      std::abort();
    for (double v : h)
      if (!std::isfinite(v)) std::abort();
  } catch (const InputError&) {
  }
  return 0;
}
