#include "pair_wearscale.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_wearscale_history.hpp"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"

namespace wearscale::dem::lammps {

using namespace LAMMPS_NS;

namespace {
constexpr const char* history_fix_id = "WEARSCALE_PAIR_HISTORY";
}

PairWearscale::PairWearscale(LAMMPS* instance) : Pair(instance) {
  single_enable = 0;
  restartinfo = 0;              // the engine sets the style and its coefficients again after a restart
  no_virial_fdotr_compute = 1;  // no global virial: the per-atom one is the engine's
  comm_reverse = 6;             // the ghosts' virials, when kept
  finitecutflag = 1;
  beyond_contact = 1;
}

PairWearscale::~PairWearscale() {
  if (fix_ != nullptr && modify->find_fix(history_fix_id) >= 0) modify->delete_fix(history_fix_id);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
  }
}

void PairWearscale::init_style() {
  if (atom->sphere_flag == 0) error->all(FLERR, std::string("Pair style ") + force->pair_style + " requires atom style sphere");
  if (comm->ghost_velocity == 0) error->all(FLERR, std::string("Pair style ") + force->pair_style + " requires ghost atoms store velocity");
  if (force->newton_pair == 0)
    error->all(FLERR, std::string("Pair style ") + force->pair_style + " runs with newton_pair on (each pair once)");
  neighbor->request(this, instance_me);
  const int at = modify->find_fix(history_fix_id);
  if (at < 0) {
    modify->add_fix(std::string(history_fix_id) + " all wearscale/history");
    fix_ = dynamic_cast<FixWearscaleHistory*>(modify->fix[modify->find_fix(history_fix_id)]);
  } else {
    fix_ = dynamic_cast<FixWearscaleHistory*>(modify->fix[at]);
  }
  if (fix_ == nullptr) error->all(FLERR, std::string("Fix ") + history_fix_id + " is not wearscale/history");
  fix_->set_pair(this);
}

double PairWearscale::max_radius() const {
  double local = 0.0;
  for (int i = 0; i < atom->nlocal; ++i) local = std::max(local, atom->radius[i]);
  double all = 0.0;
  MPI_Allreduce(&local, &all, 1, MPI_DOUBLE, MPI_MAX, world);
  return all;
}

double PairWearscale::init_one(int, int) {
  // Every pair closer than r_i + r_j + reach: the largest radii bound it.
  const double r = max_radius();
  return 2.0 * r + reach(r);
}

double PairWearscale::memory_usage() {
  return static_cast<double>((history_.capacity() + virial_.capacity()) * sizeof(double) +
                             first_.capacity() * sizeof(long long));
}

void PairWearscale::store_histories(FixWearscaleHistory& fix) const {
  auto& contacts = fix.contacts();
  double** x = atom->x;
  const tagint* tag = atom->tag;
  const int inum = list->inum;
  for (int ii = 0; ii < inum; ++ii) {
    const int i = list->ilist[ii];
    const int* jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; ++jj) {
      const auto k = static_cast<std::size_t>(first_[static_cast<std::size_t>(ii)] + jj);
      const double* h = &history_[3 * k];
      if (h[0] == 0.0 && h[1] == 0.0 && h[2] == 0.0) continue;
      const int j = jlist[jj] & NEIGHMASK;
      const double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      auto& ci = contacts[static_cast<std::size_t>(i)];
      ci.insert(ci.end(), {static_cast<double>(tag[j]), d[0], d[1], d[2], h[0], h[1], h[2]});
      // Seen from j: the opposite separation and sliding distance (a ghost's
      // go to its owner, FixWearscaleHistory::store).
      auto& cj = contacts[static_cast<std::size_t>(j)];
      cj.insert(cj.end(), {static_cast<double>(tag[i]), -d[0], -d[1], -d[2], -h[0], -h[1], -h[2]});
    }
  }
}

void PairWearscale::load_histories(const FixWearscaleHistory& fix, bool setup) {
  const auto& contacts = fix.contacts();
  double** x = atom->x;
  const double* radius = atom->radius;
  const tagint* tag = atom->tag;
  const int inum = list->inum;
  first_.assign(static_cast<std::size_t>(inum) + 1, 0);
  for (int ii = 0; ii < inum; ++ii)
    first_[static_cast<std::size_t>(ii) + 1] = first_[static_cast<std::size_t>(ii)] + list->numneigh[list->ilist[ii]];
  history_.assign(3 * static_cast<std::size_t>(first_.back()), 0.0);
  // A record is the pair's when its partner is the same atom and its
  // separation the nearest, closer than half the shortest periodic length
  // (two images of one partner are a box length apart; a contact moves by
  // less than the skin between two builds).
  double tolerance = std::numeric_limits<double>::max();
  for (int a = 0; a < 3; ++a)
    if (domain->periodicity[a]) tolerance = std::min(tolerance, 0.5 * domain->prd[a]);
  const double tolerance2 = tolerance < std::numeric_limits<double>::max() ? tolerance * tolerance : tolerance;
  const bool touching = touching_only_ && !setup;
  constexpr int rec = FixWearscaleHistory::record;
  for (int ii = 0; ii < inum; ++ii) {
    const int i = list->ilist[ii];
    const auto& ci = contacts[static_cast<std::size_t>(i)];
    if (ci.empty()) continue;
    const int* jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; ++jj) {
      const int j = jlist[jj] & NEIGHMASK;
      const double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      if (touching) {
        const double contact = radius[i] + radius[j];
        if (!(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < contact * contact)) continue;  // starts afresh
      }
      const auto partner = static_cast<double>(tag[j]);
      const double* best = nullptr;
      double nearest = tolerance2;
      for (std::size_t r = 0; r < ci.size(); r += rec) {
        if (ci[r] != partner) continue;
        const double e[3] = {ci[r + 1] - d[0], ci[r + 2] - d[1], ci[r + 3] - d[2]};
        const double miss = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
        if (miss < nearest) {
          nearest = miss;
          best = &ci[r + 4];
        }
      }
      if (best == nullptr) continue;
      const auto k = static_cast<std::size_t>(first_[static_cast<std::size_t>(ii)] + jj);
      std::copy(best, best + 3, &history_[3 * k]);
    }
  }
  loaded_ = true;
  prepare_pairs();
}

int PairWearscale::pack_reverse_comm(int n, int first, double* buf) {
  int m = 0;
  for (int i = first; i < first + n; ++i)
    for (int c = 0; c < 6; ++c) buf[m++] = virial_[6 * static_cast<std::size_t>(i) + static_cast<std::size_t>(c)];
  return m;
}

void PairWearscale::unpack_reverse_comm(int n, int* atoms, double* buf) {
  int m = 0;
  for (int k = 0; k < n; ++k)
    for (int c = 0; c < 6; ++c) virial_[6 * static_cast<std::size_t>(atoms[k]) + static_cast<std::size_t>(c)] += buf[m++];
}

}  // namespace wearscale::dem::lammps
