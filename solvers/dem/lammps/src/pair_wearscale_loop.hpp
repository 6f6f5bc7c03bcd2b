#pragma once
// The pair loop of wearscale's LAMMPS pair styles (pair_wearscale.hpp), a
// template on the law so that its pair force is inlined: over the half list,
// the force on i and −force on j (a ghost's goes to its owner with LAMMPS'
// reverse communication), the torques r n × F_T on both, the history of
// each entry carried and updated, and the per-atom virial when kept.
#include <algorithm>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "neigh_list.h"
#include "pair_wearscale.hpp"
#include "update.h"

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
  if (track_virial_) virial_.assign(6 * static_cast<std::size_t>(all), 0.0);
  double* vir = virial_.data();
  const int inum = list->inum;
  for (int ii = 0; ii < inum; ++ii) {
    const int i = list->ilist[ii];
    const int* jlist = list->firstneigh[i];
    const int jnum = list->numneigh[i];
    const Vec3 xi{x[i][0], x[i][1], x[i][2]}, vi{v[i][0], v[i][1], v[i][2]}, wi{omega[i][0], omega[i][1], omega[i][2]};
    const double ri = radius[i], mi = rmass[i];
    Vec3 fi{}, ti{};
    double* history = &history_[3 * static_cast<std::size_t>(first_[static_cast<std::size_t>(ii)])];
    for (int jj = 0; jj < jnum; ++jj, history += 3) {
      const int j = jlist[jj] & NEIGHMASK;
      const double rj = radius[j];
      const PairKinematics s{Vec3{x[j][0], x[j][1], x[j][2]} - xi, vi - Vec3{v[j][0], v[j][1], v[j][2]},
                             ri * wi + rj * Vec3{omega[j][0], omega[j][1], omega[j][2]}, ri, rj, mi, rmass[j]};
      double updated[3];
      const PairResult r = law.contact(s, history, updated, dt, advance, first_[static_cast<std::size_t>(ii)] + jj);
      std::copy(updated, updated + 3, history);
      if (!r.active) continue;
      const Vec3 arm = cross(r.normal, r.tangential);
      fi += r.force;
      ti += ri * arm;
      if (track_virial_) detail::add_outer(vir + 6 * static_cast<std::size_t>(i), s.d, r.force);
      f[j][0] -= r.force.x;
      f[j][1] -= r.force.y;
      f[j][2] -= r.force.z;
      const Vec3 tj = rj * arm;
      torque[j][0] += tj.x;
      torque[j][1] += tj.y;
      torque[j][2] += tj.z;
      if (track_virial_) detail::add_outer(vir + 6 * static_cast<std::size_t>(j), s.d, r.force);
    }
    f[i][0] += fi.x;
    f[i][1] += fi.y;
    f[i][2] += fi.z;
    torque[i][0] += ti.x;
    torque[i][1] += ti.y;
    torque[i][2] += ti.z;
  }
  if (track_virial_) comm->reverse_comm_pair(this);  // the ghosts' shares to their owners
}

}  // namespace wearscale::dem::lammps
