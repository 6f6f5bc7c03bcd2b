#pragma once
// The cohesive pair force of §6.1, (6.2)-(6.5), on one pair: the one kernel
// that CohesiveLaw's pair loop (cohesive_law.cpp) and the LAMMPS pair style
// wearscale/cohesive (solvers/dem/lammps) both run, so that the two engines
// compute the same bits from one source. Straight-line arithmetic (every
// branch of (6.3) and of the cap computed, the one that applies selected),
// inlined into the batched pair loop, which vectorises it.
#include <algorithm>
#include <cmath>

#include "wearscale/dem/cohesive_law.hpp"
#include "wearscale/dem/contact_law.hpp"
#include "wearscale/dem/coulomb_cap.hpp"

namespace wearscale::dem {

/// The force of the pair of parameters `p` in state `s`, its tangential
/// history ξ (three doubles) read from `hist` and written to `updated`
/// (every double; cleared out of reach). `advance`: the step's evaluation,
/// in which ξ integrates the sliding velocity over `dt`; otherwise it stays.
/// Without `Cohesion` the normal force is repulsion only; without
/// `Tangential` there is no tangential force and ξ stays.
template <bool Cohesion, bool Tangential>
[[gnu::always_inline]] inline PairForce cohesive_contact(const CohesivePair& p, const PairState& s, const double* hist,
                                                         double* updated, double dt, bool advance) {
  PairForce out;
  const double r2 = dot(s.d, s.d);
  const double contact = s.ri + s.rj;
  const double range = Cohesion ? contact + p.delta_f : contact;
  const bool in_range = !(r2 >= range * range);
  const double r = std::sqrt(r2);
  const Vec3 n = s.d * (1.0 / r);
  const double delta_n = r - contact;
  // (6.3): Hookean to δ_e, linear softening to δ_f, nothing beyond; without
  // cohesion, repulsion only.
  const double softening = -p.k_n * p.delta_e / (p.delta_f - p.delta_e) * (delta_n - p.delta_f);
  const double hookean = p.k_n * delta_n;
  const double cohesive_f_n = delta_n <= p.delta_e ? hookean : (delta_n <= p.delta_f ? softening : 0.0);
  const double repulsive_f_n = p.k_n * std::min(delta_n, 0.0);
  const double f_n = Cohesion ? cohesive_f_n : repulsive_f_n;
  const Vec3 vrel = s.v + cross(s.w, n);
  const double v_n = dot(vrel, n);
  const Vec3 f_normal = (f_n - p.c_n * v_n) * n;  // (6.2), normal part; positive f_n pulls i toward j
  // The sliding distance integrates the contact's tangential velocity and
  // is turned into the current tangent plane; the total tangential force,
  // spring and damping, is capped by F'_m,T (6.4)-(6.5), the spring
  // stretched back to match, as in the thesis' LAMMPS pair style
  // gran/cohesive/history (built on gran/hooke/history).
  const bool with_tangential = Tangential && p.k_t > 0.0;
  const Vec3 v_t = vrel - v_n * n;
  Vec3 xi{hist[0], hist[1], hist[2]};
  if (advance) xi += v_t * dt;
  const bool sliding = dot(xi, xi) != 0.0;
  if (advance) xi -= dot(xi, n) * n;
  Vec3 f_t = -(p.k_t * xi + p.c_t * v_t);
  const double cap = std::min((p.delta_f - delta_n) / p.delta_f, 1.0) * p.f_mt;  // (6.5)
  cap_tangential(f_t, xi, v_t * (p.c_t / p.k_t), cap, sliding);
  // Out of reach: no force, the history cleared; it moves only in a step.
  const bool store = with_tangential && advance;
  updated[0] = select(in_range, select(store, xi.x, hist[0]), 0.0);
  updated[1] = select(in_range, select(store, xi.y, hist[1]), 0.0);
  updated[2] = select(in_range, select(store, xi.z, hist[2]), 0.0);
  const Vec3 total = f_normal + f_t;
  out.force.x = with_tangential ? total.x : f_normal.x;
  out.force.y = with_tangential ? total.y : f_normal.y;
  out.force.z = with_tangential ? total.z : f_normal.z;
  out.tangential.x = with_tangential ? f_t.x : 0.0;
  out.tangential.y = with_tangential ? f_t.y : 0.0;
  out.tangential.z = with_tangential ? f_t.z : 0.0;
  out.normal = {n.x, n.y, n.z};  // by components: a whole-struct copy stops the vectoriser
  out.active = in_range;
  return out;
}

}  // namespace wearscale::dem
