#pragma once
// The pair loop of wearscale's LAMMPS pair styles (pair_wearscale.hpp), a
// template on the law so that its pair force is inlined: over the half list,
// the force on i and −force on j (a ghost's goes to its owner with LAMMPS'
// reverse communication), the torques r n × F_T on both, the history of
// each entry carried and updated, and the per-atom virial when kept.
//
// As wearscale's own loop (dem/pair_loop.hpp) it runs in batches: the
// entries' kinematics gathered as structure of arrays, the law's force over
// the batch in one loop the compiler vectorises (the law's contact() is
// straight-line arithmetic, compiled also for AVX2 and AVX-512 and picked at
// load time), then the sums in list order.
#include <algorithm>
#include <cstdint>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "neigh_list.h"
#include "pair_wearscale.hpp"
#include "update.h"
#include "wearscale/dem/pair_loop.hpp"

namespace wearscale::dem::lammps {

namespace detail {

inline void add_outer(double* w, const Vec3& d, const Vec3& f) {
  // ½ (d ⊗ f), symmetrised: the pair's share of the virial of each particle.
  w[0] += 0.5 * d.x * f.x;
  w[1] += 0.5 * d.y * f.y;
  w[2] += 0.5 * d.z * f.z;
  w[3] += 0.25 * (d.x * f.y + d.y * f.x);
  w[4] += 0.25 * (d.x * f.z + d.z * f.x);
  w[5] += 0.25 * (d.y * f.z + d.z * f.y);
}

inline constexpr std::size_t batch_entries = 128;

// One batch of consecutive list entries as structure of arrays.
struct alignas(64) EntryBatch {
  double dx[batch_entries], dy[batch_entries], dz[batch_entries];
  double vx[batch_entries], vy[batch_entries], vz[batch_entries];
  double wx[batch_entries], wy[batch_entries], wz[batch_entries];
  double ri[batch_entries], rj[batch_entries], mi[batch_entries], mj[batch_entries];
  double fx[batch_entries], fy[batch_entries], fz[batch_entries];
  double ax[batch_entries], ay[batch_entries], az[batch_entries];
  std::uint64_t active[batch_entries];  // as wide as a double: the vectoriser sizes the loop by it
  double before[3 * batch_entries], after[3 * batch_entries];
  int i[batch_entries], j[batch_entries];
};

// The law on the batch's `m` entries (from list entry k0), one lane an entry.
template <class Law, bool Advance>
WEARSCALE_PAIR_KERNEL void entry_forces(const Law& law, EntryBatch& b, std::size_t m, long long k0, double dt) {
WEARSCALE_INDEPENDENT_LANES
  for (std::size_t l = 0; l < m; ++l) {
    const PairKinematics s{{b.dx[l], b.dy[l], b.dz[l]}, {b.vx[l], b.vy[l], b.vz[l]}, {b.wx[l], b.wy[l], b.wz[l]},
                           b.ri[l], b.rj[l], b.mi[l], b.mj[l]};
    const PairResult r = law.contact(s, b.before + 3 * l, b.after + 3 * l, dt, Advance, k0 + static_cast<long long>(l));
    const Vec3 arm = cross(r.normal, r.tangential);
    b.fx[l] = r.force.x;
    b.fy[l] = r.force.y;
    b.fz[l] = r.force.z;
    b.ax[l] = arm.x;
    b.ay[l] = arm.y;
    b.az[l] = arm.z;
    b.active[l] = r.active ? 1u : 0u;
  }
}

}  // namespace detail

template <class Law>
void PairWearscale::loop(const Law& law, int eflag, int vflag) {
  ev_init(eflag, vflag);
  if (!loaded_ || static_cast<long long>(list->inum) + 1 != static_cast<long long>(first_.size()))
    error->all(FLERR, std::string("wearscale pair style: the neighbour list changed without its histories"));
  double** x = atom->x;
  double** v = atom->v;
  double** omega = atom->omega;
  double** f = atom->f;
  double** torque = atom->torque;
  const double* radius = atom->radius;
  const double* rmass = atom->rmass;
  const int all = atom->nlocal + atom->nghost;
  const bool advance = update->setupflag == 0;  // setup: the histories stay (wearscale's compute_forces)
  const double dt = update->dt;
  const bool virial = track_virial_;
  if (virial) virial_.assign(6 * static_cast<std::size_t>(all), 0.0);
  double* vir = virial_.data();
  double* history = history_.data();
  auto batch = std::make_unique<detail::EntryBatch>();
  detail::EntryBatch& b = *batch;
  const int inum = list->inum;

  // The batch's forces and torques into the atoms, in list order; its
  // updated histories back into the entries from k0 on.
  auto flush = [&](std::size_t m, long long k0) {
    if (m == 0) return;
    if (advance)
      detail::entry_forces<Law, true>(law, b, m, k0, dt);
    else
      detail::entry_forces<Law, false>(law, b, m, k0, dt);
    std::copy_n(b.after, 3 * m, history + 3 * k0);
    for (std::size_t l = 0; l < m; ++l) {
      if (b.active[l] == 0) continue;
      const int i = b.i[l], j = b.j[l];
      const Vec3 fij{b.fx[l], b.fy[l], b.fz[l]}, arm{b.ax[l], b.ay[l], b.az[l]};
      f[i][0] += fij.x;
      f[i][1] += fij.y;
      f[i][2] += fij.z;
      f[j][0] -= fij.x;
      f[j][1] -= fij.y;
      f[j][2] -= fij.z;
      const Vec3 ti = b.ri[l] * arm, tj = b.rj[l] * arm;
      torque[i][0] += ti.x;
      torque[i][1] += ti.y;
      torque[i][2] += ti.z;
      torque[j][0] += tj.x;
      torque[j][1] += tj.y;
      torque[j][2] += tj.z;
      if (virial) {
        const Vec3 d{b.dx[l], b.dy[l], b.dz[l]};
        detail::add_outer(vir + 6 * static_cast<std::size_t>(i), d, fij);
        detail::add_outer(vir + 6 * static_cast<std::size_t>(j), d, fij);
      }
    }
  };

  std::size_t m = 0;
  long long k0 = 0;
  for (int ii = 0; ii < inum; ++ii) {
    const int i = list->ilist[ii];
    const int* jlist = list->firstneigh[i];
    const int jnum = list->numneigh[i];
    long long k = first_[static_cast<std::size_t>(ii)];
    for (int jj = 0; jj < jnum; ++jj, ++k) {
      if (m == detail::batch_entries) {
        flush(m, k0);
        m = 0;
      }
      if (m == 0) k0 = k;
      const int j = jlist[jj] & NEIGHMASK;
      b.i[m] = i;
      b.j[m] = j;
      b.dx[m] = x[j][0] - x[i][0];
      b.dy[m] = x[j][1] - x[i][1];
      b.dz[m] = x[j][2] - x[i][2];
      b.vx[m] = v[i][0] - v[j][0];
      b.vy[m] = v[i][1] - v[j][1];
      b.vz[m] = v[i][2] - v[j][2];
      const double ri = radius[i], rj = radius[j];
      b.wx[m] = ri * omega[i][0] + rj * omega[j][0];
      b.wy[m] = ri * omega[i][1] + rj * omega[j][1];
      b.wz[m] = ri * omega[i][2] + rj * omega[j][2];
      b.ri[m] = ri;
      b.rj[m] = rj;
      b.mi[m] = rmass[i];
      b.mj[m] = rmass[j];
      std::copy_n(history + 3 * k, 3, b.before + 3 * m);
      ++m;
    }
  }
  flush(m, k0);
  if (virial) comm->reverse_comm_pair(this);  // the ghosts' shares to their owners
}

}  // namespace wearscale::dem::lammps
