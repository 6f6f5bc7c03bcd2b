#include "wearscale/bem/principal_stresses.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wearscale::bem {

std::array<double, 3> principal_values(double xx, double yy, double zz, double xy, double xz, double yz) {
  const double off = xy * xy + xz * xz + yz * yz;
  const double mean = (xx + yy + zz) / 3.0;
  const double dx = xx - mean, dy = yy - mean, dz = zz - mean;
  const double p2 = dx * dx + dy * dy + dz * dz + 2.0 * off;
  if (!(p2 > 1e-30 * mean * mean) || off == 0.0) {  // diagonal (or isotropic): the entries themselves
    std::array<double, 3> d{xx, yy, zz};
    std::sort(d.begin(), d.end(), std::greater<>());
    return d;
  }
  const double p = std::sqrt(p2 / 6.0);
  // det((A − mean I)/p) / 2 = cos 3φ
  const double bxx = dx / p, byy = dy / p, bzz = dz / p, bxy = xy / p, bxz = xz / p, byz = yz / p;
  const double det = bxx * (byy * bzz - byz * byz) - bxy * (bxy * bzz - byz * bxz) + bxz * (bxy * byz - byy * bxz);
  const double phi = std::acos(std::clamp(0.5 * det, -1.0, 1.0)) / 3.0;
  const double first = mean + 2.0 * p * std::cos(phi);
  const double third = mean + 2.0 * p * std::cos(phi + 2.0 * std::numbers::pi / 3.0);
  return {first, 3.0 * mean - first - third, third};
}

void principal_stresses(const StressField& s, PrincipalStresses& out) {
  const std::size_t n = s.zz.size();
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < n; ++k) {
    const auto v = principal_values(s.xx[k], s.yy[k], s.zz[k], s.xy[k], s.xz[k], s.yz[k]);
    out.first[k] = v[0];
    out.second[k] = v[1];
    out.third[k] = v[2];
    out.max_shear[k] = 0.5 * (v[0] - v[2]);  // τ_m (A.3)
  }
}

}  // namespace wearscale::bem
