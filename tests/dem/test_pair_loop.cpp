// The batched, vectorised pair loop (pair_loop.hpp) against the reference:
// each law's pair force written pair by pair with branches, as it was before the vectorised kernels
// (LAMMPS gran/hooke/history term by term; the thesis' (6.2)-(6.5)), summed
// row by row. Forces, torques and the updated tangential histories must be
// the same to rounding, in states where every branch is taken: pairs
// touching and not, Coulomb caps and cohesive caps biting, the softening
// branch of (6.3), with and without the step's history advance.
#include <algorithm>
#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <vector>

#include "wearscale/dem/anchor_block.hpp"
#include "wearscale/dem/cohesive_law.hpp"
#include "wearscale/dem/hcp_lattice.hpp"
#include "wearscale/dem/hooke_law.hpp"
#include "wearscale/dem/pair_loop.hpp"
#include "wearscale/dem/simulation.hpp"

using namespace wearscale::dem;

namespace {

struct Pair {
  Vec3 d, vi, vj, wi, wj;
  double ri, rj, mi, mj;
};

struct Reference {
  Vec3 force, tangential, normal;
  bool active = false;
  bool capped = false;     // the cap bit
  bool softening = false;  // δ_e < δ_N ≤ δ_f (cohesive)
};

// LAMMPS pair gran/hooke/history, with its branches.
Reference hooke(const HookeLaw& law, const Pair& s, double* hist, double dt, bool advance) {
  Reference out;
  const double r2 = dot(s.d, s.d), radsum = s.ri + s.rj;
  if (r2 >= radsum * radsum) {
    hist[0] = hist[1] = hist[2] = 0.0;
    return out;
  }
  const Vec3 del = -s.d;
  const double r = std::sqrt(r2), rinv = 1.0 / r, rsqinv = rinv * rinv;
  const Vec3 vr = s.vi - s.vj;
  const double vnnr = dot(vr, del);
  const Vec3 vt = vr - del * (vnnr * rsqinv);
  const Vec3 wr = (s.ri * s.wi + s.rj * s.wj) * rinv;
  const double meff = s.mi * s.mj / (s.mi + s.mj);
  const double ccel = law.k_n * (radsum - r) * rinv - meff * law.gamma_n * vnnr * rsqinv;
  const Vec3 vtr = vt + cross(del, wr);
  Vec3 shear{hist[0], hist[1], hist[2]};
  if (advance) shear += vtr * dt;
  const bool sheared = dot(shear, shear) != 0.0;
  if (advance) shear -= del * (dot(shear, del) * rsqinv);
  const double damp_t = meff * law.gamma_t;
  Vec3 fs = -(law.k_t * shear + damp_t * vtr);
  const double fs2 = dot(fs, fs), fn = law.friction * std::fabs(ccel * r);
  if (fs2 > fn * fn) {
    out.capped = true;
    if (sheared) {
      const double ratio = fn / std::sqrt(fs2);
      const Vec3 dv = vtr * (damp_t / law.k_t);
      shear = ratio * (shear + dv) - dv;
      fs *= ratio;
    } else {
      fs = {};
    }
  }
  hist[0] = shear.x, hist[1] = shear.y, hist[2] = shear.z;
  out.force = del * ccel + fs;
  out.tangential = fs;
  out.normal = s.d * rinv;
  out.active = true;
  return out;
}

// The thesis' cohesive force (6.2)-(6.5), with its branches.
Reference cohesive(const CohesiveLaw& law, const CohesivePair& p, const Pair& s, double* hist, double dt,
                   bool advance) {
  Reference out;
  const double r2 = dot(s.d, s.d), contact = s.ri + s.rj;
  const double range = law.cohesion ? contact + p.delta_f : contact;
  if (r2 >= range * range) {
    hist[0] = hist[1] = hist[2] = 0.0;
    return out;
  }
  const double r = std::sqrt(r2);
  const Vec3 n = s.d * (1.0 / r);
  const double delta_n = r - contact;
  out.softening = delta_n > p.delta_e && delta_n <= p.delta_f;
  const double f_n = law.cohesion ? normal_force(p, delta_n) : p.k_n * std::min(delta_n, 0.0);
  const Vec3 vrel = s.vi - s.vj + cross(s.ri * s.wi + s.rj * s.wj, n);
  const double v_n = dot(vrel, n);
  out.force = (f_n - p.c_n * v_n) * n;
  if (law.tangential && p.k_t > 0.0) {
    const Vec3 v_t = vrel - v_n * n;
    Vec3 xi{hist[0], hist[1], hist[2]};
    if (advance) xi += v_t * dt;
    const bool sliding = dot(xi, xi) != 0.0;
    if (advance) xi -= dot(xi, n) * n;
    Vec3 f_t = -(p.k_t * xi + p.c_t * v_t);
    const double cap = tangential_cap(p, delta_n), f2 = dot(f_t, f_t);
    if (f2 > cap * cap) {
      out.capped = true;
      if (sliding) {
        const double ratio = cap / std::sqrt(f2);
        const Vec3 lag = v_t * (p.c_t / p.k_t);
        xi = ratio * (xi + lag) - lag;
        f_t *= ratio;
      } else {
        f_t = {};
      }
    }
    if (advance) hist[0] = xi.x, hist[1] = xi.y, hist[2] = xi.z;
    out.force += f_t;
    out.tangential = f_t;
  }
  out.normal = n;
  out.active = true;
  return out;
}

struct Sums {
  std::vector<Vec3> force, torque;
  std::vector<double> history;
  int active = 0, inactive = 0, capped = 0, softening = 0;
};

// Row by row over the half list, the force on i summed locally (as before the vectorised kernels).
template <class PairForceOf>
Sums reference_sums(const Simulation& sim, const std::vector<double>& history, PairForceOf&& pair_force) {
  const auto& p = sim.particles();
  const auto& list = sim.neighbor_list();
  std::array<Vec3, PeriodicImages::max_count> shift{};
  list.shift_vectors(sim.box(), shift.data());
  Sums out{std::vector<Vec3>(p.size()), std::vector<Vec3>(p.size()), history};
  for (std::size_t i = 0; i < p.size(); ++i) {
    Vec3 fi{}, ti{};
    for (std::uint32_t k = list.offsets()[i]; k < list.offsets()[i + 1]; ++k) {
      const std::uint32_t j = list.neighbors()[k];
      const Pair s{p.position[j] + shift[list.shifts()[k]] - p.position[i], p.velocity[i], p.velocity[j],
                   p.omega[i], p.omega[j], p.radius[i], p.radius[j], p.mass[i], p.mass[j]};
      const Reference r = pair_force(i, j, k, s, out.history.data() + 3 * k);
      out.capped += r.capped ? 1 : 0;
      out.softening += r.softening ? 1 : 0;
      if (!r.active) {
        ++out.inactive;
        continue;
      }
      ++out.active;
      fi += r.force;
      out.force[j] -= r.force;
      const Vec3 arm = cross(r.normal, r.tangential);
      ti += s.ri * arm;
      out.torque[j] += s.rj * arm;
    }
    out.force[i] += fi;
    out.torque[i] += ti;
  }
  return out;
}

// The library's loop on the same state (one thread, a copy of the histories).
Sums library_sums(const Simulation& sim, const std::vector<double>& history, bool advance) {
  const auto& p = sim.particles();
  const auto& list = sim.neighbor_list();
  std::array<Vec3, PeriodicImages::max_count> shift{};
  list.shift_vectors(sim.box(), shift.data());
  Sums out{std::vector<Vec3>(p.size()), std::vector<Vec3>(p.size()), history};
  PairLoop loop;
  loop.n = p.size();
  loop.offset = list.offsets().data();
  loop.neighbor = list.neighbors().data();
  loop.image = list.shifts().data();
  loop.shift = shift.data();
  loop.history = out.history.data();
  loop.history_size = list.history_size();
  loop.x = p.position.data();
  loop.v = p.velocity.data();
  loop.w = p.omega.data();
  loop.radius = p.radius.data();
  loop.mass = p.mass.data();
  loop.force = out.force.data();
  loop.torque = out.torque.data();
  loop.dt = sim.time_step();
  loop.advance = advance;
  sim.law().add_pair_forces(loop);
  return out;
}

// The largest difference over the largest magnitude.
double mismatch(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double diff = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    diff = std::max(diff, norm(a[i] - b[i]));
    scale = std::max(scale, norm(a[i]));
  }
  return scale > 0.0 ? diff / scale : diff;
}
double mismatch(const std::vector<double>& a, const std::vector<double>& b) {
  double diff = 0.0, scale = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    diff = std::max(diff, std::fabs(a[k] - b[k]));
    scale = std::max(scale, std::fabs(a[k]));
  }
  return scale > 0.0 ? diff / scale : diff;
}

// Spins and velocities scaled up, so that contacts slide and open.
void shake(Simulation& sim, double factor, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.frozen(i)) continue;
    p.velocity[i] = {factor * u(rng), factor * u(rng), factor * u(rng)};
    p.omega[i] = {factor * u(rng) / p.radius[i], factor * u(rng) / p.radius[i], factor * u(rng) / p.radius[i]};
  }
}

void expect_same(const Sums& lib, const Sums& ref) {
  // The same operations in the same order: equal bits are expected; the
  // bound leaves room for a compiler that contracts differently.
  EXPECT_LE(mismatch(lib.force, ref.force), 1e-14);
  EXPECT_LE(mismatch(lib.torque, ref.torque), 1e-14);
  EXPECT_LE(mismatch(lib.history, ref.history), 1e-14);
}

}  // namespace

TEST(PairLoop, HookeForcesTorquesAndHistoriesAreTheReferenceLawsPairByPair) {
  auto sim = make_anchor_block({8, 10});  // 2048 spheres: one thread
  sim.run(40);                            // histories built up
  shake(sim, 2.0, 7);
  sim.run(3);
  const auto& law = sim.law_as<HookeLaw>();
  for (const bool advance : {true, false}) {
    const auto& history = sim.neighbor_list().history();
    const Sums lib = library_sums(sim, history, advance);
    const Sums ref = reference_sums(sim, history, [&](std::size_t, std::size_t, std::size_t, const Pair& s, double* h) {
      return hooke(law, s, h, sim.time_step(), advance);
    });
    expect_same(lib, ref);
    // Every branch was taken: touching and apart, the Coulomb cap biting.
    EXPECT_GT(ref.inactive, 0);
    EXPECT_GT(ref.capped, 0);
    EXPECT_GT(ref.active, ref.capped);
  }
}

TEST(PairLoop, CohesiveForcesTorquesAndHistoriesAreTheReferenceLawsPairByPair) {
  // A lattice with every site displaced at random (gaps from overlap through
  // the softening branch to beyond δ_f), random velocities, spins and
  // sliding histories; two materials on alternating sites (per-pair
  // parameters) or one (a uniform lattice: one parameter set); cohesion and
  // the tangential force on and off.
  for (const bool two_materials : {false, true})
    for (const bool cohesion : {true, false})
      for (const bool tangential : {true, false}) {
        SCOPED_TRACE(::testing::Message() << "two materials " << two_materials << ", cohesion " << cohesion
                                          << ", tangential " << tangential);
        CohesiveMaterial a = patch_test_targets(), b = a;
        a.poisson = 0.15;
        b.poisson = 0.1;
        b.young = 0.7 * a.young;
        b.name = "softer";
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        HcpLattice lattice{100.0, 4, 4, 4};
        Particles p;
        int site = 0;
        for (const auto& x : lattice.sites())
          p.add({x + Vec3{12.0 * u(rng), 12.0 * u(rng), 12.0 * u(rng)}, 50.0, 1.0, {}, two_materials ? site++ % 2 : 0,
                 0});
        Simulation sim(std::move(p), lattice.box(), CohesiveLaw({a, b}), NeighborSettings{5.0, 0, true});
        sim.set_time_step(0.1 * sim.law_as<CohesiveLaw>().critical_time_step(sim.particles()));
        shake(sim, 0.1, 5);
        sim.compute_forces();  // builds the list (with cohesion: every pair within δ_f + skin)
        sim.law_as<CohesiveLaw>().cohesion = cohesion;
        sim.law_as<CohesiveLaw>().tangential = tangential;
        std::vector<double> history(sim.neighbor_list().history().size());
        for (double& h : history) h = 3.0 * u(rng);
        const auto& law = sim.law_as<CohesiveLaw>();
        for (const bool advance : {true, false}) {
          const Sums lib = library_sums(sim, history, advance);
          const Sums ref =
              reference_sums(sim, history, [&](std::size_t i, std::size_t j, std::size_t, const Pair& s, double* h) {
                return cohesive(law, law.pair(sim.particles(), i, j), s, h, sim.time_step(), advance);
              });
          expect_same(lib, ref);
          EXPECT_GT(ref.inactive, 0);  // pairs in the list beyond reach
          if (cohesion) {
            EXPECT_GT(ref.softening, 0);
          }
          if (cohesion && tangential) {
            EXPECT_GT(ref.capped, 0);  // the cap (6.5) shrinking over the softening range
          }
        }
      }
}
