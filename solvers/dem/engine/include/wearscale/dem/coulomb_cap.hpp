#pragma once
// The Coulomb cap of a tangential spring–dashpot force f = −(k ξ + c v), as
// LAMMPS' gran/hooke/history applies it and the thesis' cohesive style keeps
// it (6.4)-(6.5): above `cap` the force is scaled to it and the spring ξ
// stretched back to match, ξ ← (cap/|f|)(ξ + v c/k) − v c/k; a capped force of
// a spring that was not stretched is dropped. Branch-free (both outcomes are
// computed, one is kept), so the batched pair loop vectorises over it.
#include <cmath>

#include "wearscale/dem/vec3.hpp"

namespace wearscale::dem {

/// Caps `f` at `cap` and stretches `xi` back to match; `lag` = v c/k,
/// `stretched`: whether ξ was non-zero before the step's rotation.
inline void cap_tangential(Vec3& f, Vec3& xi, const Vec3& lag, double cap, bool stretched) {
  const double f2 = dot(f, f);
  const bool capped = f2 > cap * cap;
  const double ratio = cap / std::sqrt(f2);
  const Vec3 pulled_back = ratio * (xi + lag) - lag;
  const Vec3 scaled = f * ratio;
  const bool rescale = capped && stretched, drop = capped && !stretched;
  xi.x = rescale ? pulled_back.x : xi.x;
  xi.y = rescale ? pulled_back.y : xi.y;
  xi.z = rescale ? pulled_back.z : xi.z;
  f.x = drop ? 0.0 : (rescale ? scaled.x : f.x);
  f.y = drop ? 0.0 : (rescale ? scaled.y : f.y);
  f.z = drop ? 0.0 : (rescale ? scaled.z : f.z);
}

}  // namespace wearscale::dem
