// The surface's scale over every process holding a slab of it.
#include "wearscale/bem/normal_operator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::bem {

SurfaceScale surface_scale(const NormalOperator& body, const RealField& h, std::string_view solver) {
  double max = -std::numeric_limits<double>::infinity(), bad = 0.0;
  for (const double v : h) {
    bad += std::isfinite(v) ? 0.0 : 1.0;
    max = std::max(max, v);
  }
  body.sum_each(bad);  // every process refuses alike
  if (bad > 0.0) throw InputError(fmt::format("{}: the surface has a NaN or infinite height", solver));
  // h_rms (1.5), the sums in storage order (as roughness.hpp's h_rms).
  const double points = static_cast<double>(body.grid().size());
  double total = 0.0;
  for (const double v : h) total += v;
  body.sum_each(total);
  const double mean = total / points;
  double squares = 0.0;
  for (const double v : h) squares += (v - mean) * (v - mean);
  body.sum_each(squares);
  SurfaceScale s;
  s.h_rms = std::sqrt(squares / points);
  if (!(s.h_rms > 0.0)) s.h_rms = 1.0;
  s.h_max = body.max(max);
  return s;
}

}  // namespace wearscale::bem
