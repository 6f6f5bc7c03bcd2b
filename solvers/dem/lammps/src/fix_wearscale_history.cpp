#include "fix_wearscale_history.hpp"

#include <algorithm>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "neighbor.h"
#include "update.h"
#include "error.h"
#include "pair_wearscale.hpp"

namespace wearscale::dem::lammps {

using namespace LAMMPS_NS;

FixWearscaleHistory::FixWearscaleHistory(LAMMPS* instance, int narg, char** arg) : Fix(instance, narg, arg) {
  if (narg != 3) error->all(FLERR, std::string("Illegal fix wearscale/history command: it takes no arguments"));
  restart_peratom = 1;
  create_attribute = 1;
  force_reneighbor = 1;
  next_reneighbor = -1;
  maxexchange_dynamic = 1;
  maxexchange = 5;
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

FixWearscaleHistory::~FixWearscaleHistory() {
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
}

int FixWearscaleHistory::setmask() {
  return FixConst::POST_INTEGRATE | FixConst::PRE_EXCHANGE | FixConst::POST_NEIGHBOR | FixConst::POST_RUN;
}

void FixWearscaleHistory::set_reference() {
  for (int i = 0; i < atom->nlocal; ++i) {
    domain->unmap(atom->x[i], atom->image[i], reference_[static_cast<std::size_t>(i)].data());
    referenced_[static_cast<std::size_t>(i)] = 1;
  }
}

// Touching-only transfer: a rebuild that drops histories is due once a
// particle has moved more than half the skin since the last one (as
// wearscale's own list rebuilds); LAMMPS rebuilds at this step then.
void FixWearscaleHistory::post_integrate() {
  if (pair_ == nullptr || !pair_->touching_only()) return;
  const double half_skin = 0.5 * neighbor->skin;
  int local = 0;
  for (int i = 0; i < atom->nlocal && local == 0; ++i) {
    const auto& r = reference_[static_cast<std::size_t>(i)];
    if (!referenced_[static_cast<std::size_t>(i)]) continue;
    double x[3];
    domain->unmap(atom->x[i], atom->image[i], x);
    const double d2 = (x[0] - r[0]) * (x[0] - r[0]) + (x[1] - r[1]) * (x[1] - r[1]) + (x[2] - r[2]) * (x[2] - r[2]);
    local = d2 > half_skin * half_skin ? 1 : 0;
  }
  int any = 0;
  MPI_Allreduce(&local, &any, 1, MPI_INT, MPI_MAX, world);
  if (any != 0) {
    next_reneighbor = update->ntimestep;
    due_ = true;
  }
}

void FixWearscaleHistory::store() {
  // Once per rebuild: after a store, the list is stale until the next load
  // (a restart written between two runs exchanges atoms on the way).
  if (stored_ || pair_ == nullptr || !pair_->loaded()) {
    refresh_exchange_size();
    return;
  }
  const int all = atom->nlocal + atom->nghost;
  if (static_cast<int>(contacts_.size()) < all) contacts_.resize(static_cast<std::size_t>(all));
  for (int i = 0; i < all; ++i) contacts_[static_cast<std::size_t>(i)].clear();
  pair_->store_histories(*this);
  comm->reverse_comm_fix_variable(this);  // the ghosts' records to their owners
  for (int i = atom->nlocal; i < all; ++i) std::vector<double>().swap(contacts_[static_cast<std::size_t>(i)]);
  stored_ = true;
  refresh_exchange_size();
}

void FixWearscaleHistory::refresh_exchange_size() {
  std::size_t most = 0;
  for (int i = 0; i < atom->nlocal; ++i) most = std::max(most, contacts_[static_cast<std::size_t>(i)].size());
  maxexchange = 5 + static_cast<int>(most);
}

void FixWearscaleHistory::setup_pre_exchange() { store(); }
void FixWearscaleHistory::pre_exchange() { store(); }
// The end of a run: the histories go to the atoms, which may be exchanged
// (a restart written) before the next run rebuilds the list.
void FixWearscaleHistory::post_run() { store(); }

void FixWearscaleHistory::setup_post_neighbor() {
  // A run's first rebuild carries every history (a run split in chunks
  // rebuilds at each); the first of all sets the reference positions.
  bool unset = false;
  for (int i = 0; i < atom->nlocal && !unset; ++i) unset = !referenced_[static_cast<std::size_t>(i)];
  if (unset) set_reference();
  if (pair_ != nullptr) pair_->load_histories(*this, true);
  for (auto& c : contacts_) std::vector<double>().swap(c);
  stored_ = false;
}

void FixWearscaleHistory::post_neighbor() {
  if (pair_ != nullptr) pair_->load_histories(*this, !due_);
  if (due_) set_reference();
  due_ = false;
  for (int i = 0; i < atom->nlocal; ++i) contacts_[static_cast<std::size_t>(i)].clear();
  stored_ = false;
}

void FixWearscaleHistory::grow_arrays(int nmax) {
  contacts_.resize(static_cast<std::size_t>(nmax));
  reference_.resize(static_cast<std::size_t>(nmax));
  referenced_.resize(static_cast<std::size_t>(nmax), 0);
}

void FixWearscaleHistory::copy_arrays(int i, int j, int) {
  contacts_[static_cast<std::size_t>(j)] = contacts_[static_cast<std::size_t>(i)];
  reference_[static_cast<std::size_t>(j)] = reference_[static_cast<std::size_t>(i)];
  referenced_[static_cast<std::size_t>(j)] = referenced_[static_cast<std::size_t>(i)];
}

// Exchanged and restarted: [reference (3), referenced, count, records...].
int FixWearscaleHistory::pack_exchange(int i, double* buf) {
  const auto k = static_cast<std::size_t>(i);
  const auto& c = contacts_[k];
  std::copy(reference_[k].begin(), reference_[k].end(), buf);
  buf[3] = referenced_[k];
  buf[4] = static_cast<double>(c.size());
  std::copy(c.begin(), c.end(), buf + 5);
  return 5 + static_cast<int>(c.size());
}

int FixWearscaleHistory::unpack_exchange(int nlocal, double* buf) {
  const auto k = static_cast<std::size_t>(nlocal);
  std::copy(buf, buf + 3, reference_[k].begin());
  referenced_[k] = buf[3] != 0.0 ? 1 : 0;
  const auto n = static_cast<std::size_t>(buf[4]);
  contacts_[k].assign(buf + 5, buf + 5 + n);
  return 5 + static_cast<int>(n);
}

int FixWearscaleHistory::pack_reverse_comm_size(int n, int first) {
  int m = 0;
  for (int i = first; i < first + n; ++i) m += 1 + static_cast<int>(contacts_[static_cast<std::size_t>(i)].size());
  return m;
}

int FixWearscaleHistory::pack_reverse_comm(int n, int first, double* buf) {
  int m = 0;
  for (int i = first; i < first + n; ++i) {
    auto& c = contacts_[static_cast<std::size_t>(i)];
    buf[m++] = static_cast<double>(c.size());
    std::copy(c.begin(), c.end(), buf + m);
    m += static_cast<int>(c.size());
    c.clear();  // sent: a ghost met again through another swap sends nothing twice
  }
  return m;
}

void FixWearscaleHistory::unpack_reverse_comm(int n, int* list, double* buf) {
  int m = 0;
  for (int k = 0; k < n; ++k) {
    const auto count = static_cast<std::size_t>(buf[m++]);
    auto& c = contacts_[static_cast<std::size_t>(list[k])];
    c.insert(c.end(), buf + m, buf + m + count);
    m += static_cast<int>(count);
  }
}

// Restart: [the part's length (itself included), then what an exchange
// carries], the layout LAMMPS expects.
int FixWearscaleHistory::pack_restart(int i, double* buf) {
  const int n = pack_exchange(i, buf + 1);
  buf[0] = static_cast<double>(1 + n);
  return 1 + n;
}

void FixWearscaleHistory::unpack_restart(int nlocal, int nth) {
  double** extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; ++k) m += static_cast<int>(extra[nlocal][m]);
  unpack_exchange(nlocal, &extra[nlocal][m + 1]);
}

int FixWearscaleHistory::size_restart(int i) { return 6 + static_cast<int>(contacts_[static_cast<std::size_t>(i)].size()); }

int FixWearscaleHistory::maxsize_restart() {
  // The largest over every rank: LAMMPS sizes the restart's per-atom buffer with it.
  int most = 0;
  for (int i = 0; i < atom->nlocal; ++i) most = std::max(most, size_restart(i));
  int all = 0;
  MPI_Allreduce(&most, &all, 1, MPI_INT, MPI_MAX, world);
  return all;
}

double FixWearscaleHistory::memory_usage() {
  double bytes = static_cast<double>(contacts_.capacity() * sizeof(std::vector<double>));
  for (const auto& c : contacts_) bytes += static_cast<double>(c.capacity() * sizeof(double));
  return bytes;
}

}  // namespace wearscale::dem::lammps
