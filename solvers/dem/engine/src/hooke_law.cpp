#include "wearscale/dem/hooke_law.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "wearscale/dem/cohesive_law.hpp"
#include "wearscale/dem/coulomb_cap.hpp"
#include "wearscale/dem/pair_loop.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/dem/particles.hpp"

namespace wearscale::dem {

// LAMMPS pair gran/hooke/history, term by term (so that the benchmark does
// the same work and the same arithmetic as the reference decks). Written as
// straight-line arithmetic for the vectorised pair loop: both sides of each
// branch of LAMMPS are computed and the taken one selected, which gives the
// same bits as branching (no operation is reordered or fused).
inline PairForce HookeLaw::contact(std::size_t, const PairState& s, const double* hist, double* updated, double dt,
                                   bool advance) const {
  PairForce out;
  const double r2 = dot(s.d, s.d);
  const double radsum = s.ri + s.rj;
  const bool touching = !(r2 >= radsum * radsum);
  const Vec3 del = -s.d;  // x_i − x_j
  const double r = std::sqrt(r2);
  const double rinv = 1.0 / r;
  const double rsqinv = rinv * rinv;
  const Vec3 vr = s.v;
  const double vnnr = dot(vr, del);
  const Vec3 vn = del * (vnnr * rsqinv);
  const Vec3 vt = vr - vn;
  const Vec3 wr = s.w * rinv;
  const double meff = s.mi * s.mj / (s.mi + s.mj);
  const double damp = meff * gamma_n * vnnr * rsqinv;
  const double ccel = k_n * (radsum - r) * rinv - damp;
  const Vec3 vtr = vt + cross(del, wr);
  Vec3 shear{hist[0], hist[1], hist[2]};
  if (advance) shear += vtr * dt;
  const bool sheared = dot(shear, shear) != 0.0;  // LAMMPS tests |shear| != 0 before the rotation
  if (advance) shear -= del * (dot(shear, del) * rsqinv);
  const double damp_t = meff * gamma_t;
  Vec3 fs = -(k_t * shear + damp_t * vtr);
  const double fn = friction * std::fabs(ccel * r);
  cap_tangential(fs, shear, vtr * (damp_t / k_t), fn, sheared);  // Coulomb cap
  // A pair out of contact has no force and forgets its history.
  updated[0] = touching ? shear.x : 0.0;
  updated[1] = touching ? shear.y : 0.0;
  updated[2] = touching ? shear.z : 0.0;
  out.force = del * ccel + fs;
  out.tangential = fs;
  out.normal = s.d * rinv;
  out.active = touching;
  return out;
}

void HookeLaw::add_pair_forces(PairLoop& loop) const { run_pair_loop(*this, loop); }

double HookeLaw::critical_time_step(const Particles& p) const {
  double lightest = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.wall[i] == no_wall) lightest = std::min(lightest, p.mass[i]);
  return dem::critical_time_step(lightest, k_n);  // (6.6)
}

void HookeLaw::add_pair_energy(const Particles&, std::size_t, std::size_t, std::size_t, double delta,
                               const double* h, double& e) const {
  if (delta < 0.0) e += 0.5 * k_n * delta * delta;
  e += 0.5 * k_t * (h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
}

}  // namespace wearscale::dem

// From a case: the springs and dampers of the cohesive law (6.54)-(6.60)
// for two particles of the first material at the case's diameter d0, without
// cohesion, and Coulomb friction μ = `friction` in place of the cap (6.5).
WEARSCALE_CONTACT_LAW(hooke, "linear spring-dashpot with Coulomb friction (LAMMPS gran/hooke/history)",
                      [](const ContactLawInputs& in) {
                        using namespace wearscale::dem;
                        if (in.materials.empty() || !(in.diameter > 0.0))
                          throw wearscale::InputError("the hooke DEM law needs a material and a diameter d0 > 0");
                        const auto& m = in.materials.front();
                        const double r = 0.5 * in.diameter;
                        const double mass = m.density * 4.0 / 3.0 * std::numbers::pi * r * r * r;
                        const CohesivePair p = cohesive_pair(m, r, r, mass, mass);
                        const double m_eff = 0.5 * mass;
                        return std::make_unique<HookeLaw>(p.k_n, p.k_t, p.c_n / m_eff, p.c_t / m_eff, in.friction);
                      })
