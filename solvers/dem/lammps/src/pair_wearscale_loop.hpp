#pragma once
// The pair loop of wearscale's LAMMPS pair styles (pair_wearscale.hpp), a
// template on the law so that its pair force is inlined: over the half list,
// the force on i and −force on j (a ghost's goes to its owner with LAMMPS'
// reverse communication), the torques r n × F_T on both, the history of
// each entry carried and updated, and the per-atom virial when kept.
//
// It is wearscale's own batch (dem/pair_loop.hpp) with LAMMPS' arrays
// around it: the entries' kinematics gathered into a detail::Batch, the
// law's force over the batch by detail::batch_forces (one loop the compiler
// vectorises, compiled also for AVX2 and AVX-512 and picked at load time),
// then the sums in list order.
#include <cstddef>
#include <memory>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "neigh_list.h"
#include "pair_wearscale.hpp"
#include "update.h"
#include "wearscale/dem/pair_loop.hpp"

namespace wearscale::dem::lammps {

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
  constexpr std::size_t batch = dem::detail::batch_pairs;
  auto gathered = std::make_unique<dem::detail::Batch>();
  dem::detail::Batch& b = *gathered;
  int bi[batch], bj[batch];  // the atoms of each of the batch's entries
  const int inum = list->inum;

  // The batch's forces and torques into the atoms, in list order; its
  // updated histories back into the entries from k0 on.
  auto flush = [&](std::size_t m, long long k0) {
    if (m == 0) return;
    const auto first = static_cast<std::size_t>(k0);
    if (advance)
      dem::detail::batch_forces<Law, 3, true>(law, b, first, m, history, 3, dt);
    else
      dem::detail::batch_forces<Law, 3, false>(law, b, first, m, history, 3, dt);
    for (std::size_t l = 0; l < m; ++l) {
      if (b.active[l] == 0) continue;
      const int i = bi[l], j = bj[l];
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
        dem::detail::add_outer(vir + 6 * static_cast<std::size_t>(i), d, fij);
        dem::detail::add_outer(vir + 6 * static_cast<std::size_t>(j), d, fij);
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
      if (m == batch) {
        flush(m, k0);
        m = 0;
      }
      if (m == 0) k0 = k;
      const int j = jlist[jj] & NEIGHMASK;
      bi[m] = i;
      bj[m] = j;
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
      ++m;
    }
  }
  flush(m, k0);
  if (virial) comm->reverse_comm_pair(this);  // the ghosts' shares to their owners
}

}  // namespace wearscale::dem::lammps
