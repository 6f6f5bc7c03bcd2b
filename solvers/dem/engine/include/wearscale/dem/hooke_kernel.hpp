#pragma once
// The linear spring-dashpot pair force of LAMMPS' gran/hooke/history, term
// by term, on one pair: the one kernel that HookeLaw's pair loop
// (hooke_law.cpp) and the LAMMPS pair style wearscale/hooke
// (solvers/dem/lammps) both run, so that the two engines compute the same
// bits from one source. Straight-line arithmetic (both sides of each of
// LAMMPS' branches computed, the taken one selected: the same bits as
// branching, no operation reordered or fused), inlined into the batched pair
// loop, which vectorises it.
#include <cmath>

#include "wearscale/dem/contact_law.hpp"
#include "wearscale/dem/coulomb_cap.hpp"

namespace wearscale::dem {

/// The law's constants: normal force k_N δ − m_eff γ_N v_N, tangential
/// spring k_T with damping m_eff γ_T, capped at μ|F_N|.
struct HookeSprings {
  double k_n, k_t, gamma_n, gamma_t, friction;
};

/// The force of a pair in state `s`, its shear history (three doubles) read
/// from `hist` and written to `updated` (cleared out of contact);
/// `advance`: the step's evaluation, in which the history integrates the
/// sliding velocity over `dt`.
[[gnu::always_inline]] inline PairForce hooke_contact(const HookeSprings& h, const PairState& s, const double* hist,
                                                      double* updated, double dt, bool advance) {
  PairForce out;
  const double r2 = dot(s.d, s.d);
  const double radsum = s.ri + s.rj;
  const bool touching = !(r2 >= radsum * radsum);
  const Vec3 del = -s.d;  // x_i − x_j
  const double r = std::sqrt(r2);
  const double rinv = 1.0 / r;
  const double rsqinv = rinv * rinv;
  const double vnnr = dot(s.v, del);
  const Vec3 vt = s.v - del * (vnnr * rsqinv);
  const Vec3 wr = s.w * rinv;
  const double meff = s.mi * s.mj / (s.mi + s.mj);
  const double damp = meff * h.gamma_n * vnnr * rsqinv;
  const double ccel = h.k_n * (radsum - r) * rinv - damp;
  const Vec3 vtr = vt + cross(del, wr);
  Vec3 shear{hist[0], hist[1], hist[2]};
  if (advance) shear += vtr * dt;
  const bool sheared = dot(shear, shear) != 0.0;  // LAMMPS tests |shear| != 0 before the rotation
  if (advance) shear -= del * (dot(shear, del) * rsqinv);
  const double damp_t = meff * h.gamma_t;
  Vec3 fs = -(h.k_t * shear + damp_t * vtr);
  cap_tangential(fs, shear, vtr * (damp_t / h.k_t), h.friction * std::fabs(ccel * r), sheared);  // Coulomb cap
  // Apart: no force, no history. By components (a whole-struct copy stops the vectoriser).
  updated[0] = touching ? shear.x : 0.0;
  updated[1] = touching ? shear.y : 0.0;
  updated[2] = touching ? shear.z : 0.0;
  const Vec3 total = del * ccel + fs, n = s.d * rinv;
  out.force = {total.x, total.y, total.z};
  out.tangential = {fs.x, fs.y, fs.z};
  out.normal = {n.x, n.y, n.z};
  out.active = touching;
  return out;
}

}  // namespace wearscale::dem
