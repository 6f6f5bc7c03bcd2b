// Fuzzes the readers of instruments' files (X3P, Gwyddion .gwy/.gsf/ASCII,
// Digital Surf, SDF): any bytes give a finite height grid of the size the
// file says, or InputError naming the problem. The HDF5-based .datx is read
// through libhdf5 from a file and is not fuzzed here.
// First byte: bit 0 fills missing points (else refuses them), bit 1 gives
// the size as the caller would; the rest is the file.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "wearscale/core/errors.hpp"
#include "wearscale/io/topography_io.hpp"

using namespace wearscale;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  bem::TopographyOptions options;
  options.missing = (data[0] & 1) ? bem::MissingPoints::Fill : bem::MissingPoints::Refuse;
  if (data[0] & 2) options.size.lx = options.size.ly = 1e-3;
  options.max_points = std::size_t(1) << 16;  // a hostile header is refused before it allocates
  const std::string_view bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    const auto t = bem::parse_measured_topography(bytes, "fuzz.dat", options);
    const Grid2D& g = t.heights.grid();
    if (g.nx == 0 || g.ny == 0 || t.heights.size() != g.nx * g.ny || g.size() > options.max_points ||
        !(g.lx > 0.0) || !(g.ly > 0.0) || !std::isfinite(g.lx) || !std::isfinite(g.ly))
      std::abort();
    if (t.missing > 0 && options.missing == bem::MissingPoints::Refuse) std::abort();
    for (double v : t.heights)
      if (!std::isfinite(v)) std::abort();
  } catch (const InputError&) {
  }
  return 0;
}
