#include "fix_wearscale_verlet.hpp"

#include <algorithm>
#include <cmath>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "timer.h"
#include "update.h"
#include "utils.h"

namespace wearscale::dem::lammps {

using namespace LAMMPS_NS;

FixWearscaleVerlet::FixWearscaleVerlet(LAMMPS* instance, int narg, char** arg) : Fix(instance, narg, arg) {
  if (narg != 4) error->all(FLERR, std::string("Illegal fix wearscale/verlet command: fix ID all wearscale/verlet SKIN"));
  skin_ = utils::numeric(FLERR, arg[3], false, lmp);
  if (!(skin_ > 0.0)) error->all(FLERR, std::string("Illegal fix wearscale/verlet command: SKIN > 0"));
  time_integrate = 1;
  nevery = 1;
  restart_peratom = 1;
  maxexchange = 7;
  grow_arrays(atom->nmax);
  atom->add_callback(LAMMPS_NS::Atom::GROW);
  atom->add_callback(LAMMPS_NS::Atom::RESTART);
}

FixWearscaleVerlet::~FixWearscaleVerlet() {
  atom->delete_callback(id, LAMMPS_NS::Atom::GROW);
  atom->delete_callback(id, LAMMPS_NS::Atom::RESTART);
}

int FixWearscaleVerlet::setmask() {
  return FixConst::INITIAL_INTEGRATE | FixConst::POST_INTEGRATE | FixConst::POST_FORCE | FixConst::FINAL_INTEGRATE |
         FixConst::END_OF_STEP | FixConst::POST_RUN;
}

void FixWearscaleVerlet::init() {
  if (atom->sphere_flag == 0) error->all(FLERR, std::string("Fix wearscale/verlet requires atom style sphere"));
}

int FixWearscaleVerlet::wall_of(int mask) const {
  for (std::size_t w = 0; w < walls.size(); ++w)
    if (mask & walls[w].groupbit) return static_cast<int>(w);
  return -1;
}

double FixWearscaleVerlet::acceleration(const WallSlot& w) const {
  const auto& m = w.motion;
  const double load = -static_cast<double>(m.outward) * m.pressure * m.area;
  return (w.force[m.axis] + load - m.damping * w.velocity[m.axis]) / w.mass;
}

void FixWearscaleVerlet::fail(int kind, long long tag, double value) {
  if (failure_.kind >= kind) return;
  failure_ = {kind, tag, value, steps + 1};
}

// The first half-kick and drift of (6.1); the walls move at their velocity
// (a pressed wall's first takes half a kick from the net force on it).
void FixWearscaleVerlet::initial_integrate(int) {
  const double dt = update->dt, half = 0.5 * dt;
  std::vector<Vec3> moved(walls.size());
  for (std::size_t w = 0; w < walls.size(); ++w) {
    auto& wall = walls[w];
    if (wall.motion.kind == WallMotion::Kind::Pressure) wall.velocity[wall.motion.axis] += half * acceleration(wall);
    moved[w] = dt * wall.velocity;
    wall.displacement += moved[w];
  }
  double** x = atom->x;
  double** v = atom->v;
  double** f = atom->f;
  double** omega = atom->omega;
  double** torque = atom->torque;
  const double* rmass = atom->rmass;
  const double* radius = atom->radius;
  const int* mask = atom->mask;
  const tagint* tag = atom->tag;
  for (int i = 0; i < atom->nlocal; ++i) {
    const int w = wall_of(mask[i]);
    if (w >= 0) {
      const auto& wall = walls[static_cast<std::size_t>(w)];
      for (int a = 0; a < 3; ++a) {
        x[i][a] += moved[static_cast<std::size_t>(w)][a];
        v[i][a] = wall.velocity[a];
        omega[i][a] = 0.0;
      }
      continue;
    }
    const double inv_mass = 1.0 / rmass[i];
    const double inv_inertia = 1.0 / (0.4 * rmass[i] * radius[i] * radius[i]);  // solid sphere I = 2mr²/5
    Vec3 vi{v[i][0], v[i][1], v[i][2]};
    vi += (half * inv_mass) * Vec3{f[i][0], f[i][1], f[i][2]};
    const double speed = std::sqrt(dot(vi, vi));
    if (!std::isfinite(speed)) {
      fail(RunFailure::non_finite, tag[i], speed);
      continue;  // left where it was: a run that failed ends after this step
    }
    if (speed * dt > skin_) {
      fail(RunFailure::skin, tag[i], speed * dt);
      continue;
    }
    for (int a = 0; a < 3; ++a) {
      v[i][a] = vi[a];
      x[i][a] += dt * vi[a];
      omega[i][a] += (half * inv_inertia) * torque[i][a];
    }
  }
}

// Every rank learns at once whether a particle failed, and the run ends
// after this step (before the next one moves anything).
void FixWearscaleVerlet::post_integrate() {
  int local = failure_.kind, worst = 0;
  MPI_Allreduce(&local, &worst, 1, MPI_INT, MPI_MAX, world);
  if (worst != RunFailure::none) timer->force_timeout();
}

RunFailure FixWearscaleVerlet::agree_on_failure() {
  int local = failure_.kind, worst = 0;
  MPI_Allreduce(&local, &worst, 1, MPI_INT, MPI_MAX, world);
  if (worst == RunFailure::none) return {};
  // The lowest tag among the ranks that saw the worst kind.
  double mine[3] = {failure_.kind == worst ? static_cast<double>(failure_.tag) : 1e300, failure_.value,
                    static_cast<double>(failure_.step)};
  struct {
    double tag;
    int rank;
  } in{mine[0], comm->me}, out{};
  MPI_Allreduce(&in, &out, 1, MPI_DOUBLE_INT, MPI_MINLOC, world);
  MPI_Bcast(mine, 3, MPI_DOUBLE, out.rank, world);
  failure_ = {};
  return {worst, static_cast<long long>(mine[0]), mine[1], static_cast<long long>(mine[2])};
}

// The run's first forces: those of the last step, kept (their damping is in
// them), or computed now.
void FixWearscaleVerlet::setup(int vflag) {
  bool kept = continue_forces;
  for (int i = 0; i < atom->nlocal && kept; ++i) kept = kept_[static_cast<std::size_t>(i)][6] != 0.0;
  int local = kept ? 1 : 0, all = 0;
  MPI_Allreduce(&local, &all, 1, MPI_INT, MPI_MIN, world);
  if (all == 0) {
    post_force(vflag);
    return;
  }
  for (int i = 0; i < atom->nlocal; ++i)
    for (int a = 0; a < 3; ++a) {
      atom->f[i][a] = kept_[static_cast<std::size_t>(i)][static_cast<std::size_t>(a)];
      atom->torque[i][a] = kept_[static_cast<std::size_t>(i)][3 + static_cast<std::size_t>(a)];
    }
  sum_wall_forces();
}

void FixWearscaleVerlet::post_run() {
  for (int i = 0; i < atom->nlocal; ++i) {
    auto& k = kept_[static_cast<std::size_t>(i)];
    for (int a = 0; a < 3; ++a) {
      k[static_cast<std::size_t>(a)] = atom->f[i][a];
      k[3 + static_cast<std::size_t>(a)] = atom->torque[i][a];
    }
    k[6] = 1.0;
  }
}

void FixWearscaleVerlet::grow_arrays(int nmax) { kept_.resize(static_cast<std::size_t>(nmax)); }

void FixWearscaleVerlet::copy_arrays(int i, int j, int) {
  kept_[static_cast<std::size_t>(j)] = kept_[static_cast<std::size_t>(i)];
}

int FixWearscaleVerlet::pack_exchange(int i, double* buf) {
  std::copy(kept_[static_cast<std::size_t>(i)].begin(), kept_[static_cast<std::size_t>(i)].end(), buf);
  return 7;
}

int FixWearscaleVerlet::unpack_exchange(int nlocal, double* buf) {
  std::copy(buf, buf + 7, kept_[static_cast<std::size_t>(nlocal)].begin());
  return 7;
}

int FixWearscaleVerlet::pack_restart(int i, double* buf) {
  buf[0] = 8.0;
  return 1 + pack_exchange(i, buf + 1);
}

void FixWearscaleVerlet::unpack_restart(int nlocal, int nth) {
  double** extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; ++k) m += static_cast<int>(extra[nlocal][m]);
  unpack_exchange(nlocal, &extra[nlocal][m + 1]);
}

// Global damping on the mobile particles, then the net force on each wall.
void FixWearscaleVerlet::post_force(int) {
  double** v = atom->v;
  double** f = atom->f;
  const int* mask = atom->mask;
  if (damping > 0.0)
    for (int i = 0; i < atom->nlocal; ++i)
      if (wall_of(mask[i]) < 0)
        for (int a = 0; a < 3; ++a) f[i][a] -= damping * v[i][a];
  sum_wall_forces();
}

void FixWearscaleVerlet::sum_wall_forces() {
  if (walls.empty()) return;
  const std::size_t n = 3 * walls.size();
  std::vector<double> local(n, 0.0);
  double** f = atom->f;
  const int* mask = atom->mask;
  for (int i = 0; i < atom->nlocal; ++i) {
    const int w = wall_of(mask[i]);
    if (w < 0) continue;
    for (int a = 0; a < 3; ++a) local[3 * static_cast<std::size_t>(w) + static_cast<std::size_t>(a)] += f[i][a];
  }
  // Added in rank order on every rank: the same bits whatever the reduction tree.
  sums_.resize(n * static_cast<std::size_t>(comm->nprocs));
  MPI_Allgather(local.data(), static_cast<int>(n), MPI_DOUBLE, sums_.data(), static_cast<int>(n), MPI_DOUBLE, world);
  for (std::size_t w = 0; w < walls.size(); ++w)
    for (int a = 0; a < 3; ++a) {
      double s = 0.0;
      for (int r = 0; r < comm->nprocs; ++r) s += sums_[static_cast<std::size_t>(r) * n + 3 * w + static_cast<std::size_t>(a)];
      walls[w].force[a] = s;
    }
}

// The second half-kick of (6.1); a pressed wall takes the other half of its own.
void FixWearscaleVerlet::final_integrate() {
  const double half = 0.5 * update->dt;
  double** v = atom->v;
  double** f = atom->f;
  double** omega = atom->omega;
  double** torque = atom->torque;
  const double* rmass = atom->rmass;
  const double* radius = atom->radius;
  const int* mask = atom->mask;
  const tagint* tag = atom->tag;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (wall_of(mask[i]) >= 0) continue;
    const double inv_mass = 1.0 / rmass[i];
    const double inv_inertia = 1.0 / (0.4 * rmass[i] * radius[i] * radius[i]);
    for (int a = 0; a < 3; ++a) {
      v[i][a] += (half * inv_mass) * f[i][a];
      omega[i][a] += (half * inv_inertia) * torque[i][a];
    }
    if (!std::isfinite(v[i][0] + v[i][1] + v[i][2])) fail(RunFailure::non_finite, tag[i], v[i][0] + v[i][1] + v[i][2]);
  }
  for (auto& wall : walls)
    if (wall.motion.kind == WallMotion::Kind::Pressure) wall.velocity[wall.motion.axis] += half * acceleration(wall);
}

void FixWearscaleVerlet::end_of_step() {
  ++steps;
  time += update->dt;
  if (each_step) each_step();
}

}  // namespace wearscale::dem::lammps
