#include "fix_wearscale_history.hpp"

#include <algorithm>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "pair_wearscale.hpp"

namespace wearscale::dem::lammps {

using namespace LAMMPS_NS;

FixWearscaleHistory::FixWearscaleHistory(LAMMPS* instance, int narg, char** arg) : Fix(instance, narg, arg) {
  if (narg != 3) error->all(FLERR, std::string("Illegal fix wearscale/history command: it takes no arguments"));
  restart_peratom = 1;
  create_attribute = 1;
  maxexchange_dynamic = 1;
  maxexchange = 1;
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

FixWearscaleHistory::~FixWearscaleHistory() {
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
}

int FixWearscaleHistory::setmask() {
  return FixConst::PRE_EXCHANGE | FixConst::POST_NEIGHBOR | FixConst::POST_RUN;
}

void FixWearscaleHistory::store() {
  // Once per rebuild: after a store, the list is stale until the next load
  // (a restart written between two runs exchanges atoms on the way).
  if (stored_ || pair_ == nullptr || !pair_->loaded()) {
    refresh_exchange_size();
    return;
  }
  for (int i = 0; i < atom->nlocal; ++i) contacts_[static_cast<std::size_t>(i)].clear();
  pair_->store_histories(*this);
  stored_ = true;
  refresh_exchange_size();
}

void FixWearscaleHistory::refresh_exchange_size() {
  std::size_t most = 0;
  for (int i = 0; i < atom->nlocal; ++i) most = std::max(most, contacts_[static_cast<std::size_t>(i)].size());
  maxexchange = 1 + static_cast<int>(most);
}

void FixWearscaleHistory::setup_pre_exchange() { store(); }
void FixWearscaleHistory::pre_exchange() { store(); }
// The end of a run: the histories go to the atoms, which may be exchanged
// (a restart written) before the next run rebuilds the list.
void FixWearscaleHistory::post_run() { store(); }

void FixWearscaleHistory::setup_post_neighbor() {
  if (pair_ != nullptr) pair_->load_histories(*this, true);
  for (auto& c : contacts_) std::vector<double>().swap(c);
  stored_ = false;
}

void FixWearscaleHistory::post_neighbor() {
  if (pair_ != nullptr) pair_->load_histories(*this, false);
  for (int i = 0; i < atom->nlocal; ++i) contacts_[static_cast<std::size_t>(i)].clear();
  stored_ = false;
}

void FixWearscaleHistory::grow_arrays(int nmax) { contacts_.resize(static_cast<std::size_t>(nmax)); }

void FixWearscaleHistory::copy_arrays(int i, int j, int) {
  contacts_[static_cast<std::size_t>(j)] = contacts_[static_cast<std::size_t>(i)];
}

int FixWearscaleHistory::pack_exchange(int i, double* buf) {
  const auto& c = contacts_[static_cast<std::size_t>(i)];
  buf[0] = static_cast<double>(c.size());
  std::copy(c.begin(), c.end(), buf + 1);
  return 1 + static_cast<int>(c.size());
}

int FixWearscaleHistory::unpack_exchange(int nlocal, double* buf) {
  const auto n = static_cast<std::size_t>(buf[0]);
  contacts_[static_cast<std::size_t>(nlocal)].assign(buf + 1, buf + 1 + n);
  return 1 + static_cast<int>(n);
}

// Restart: [values in this fix's part, count, records...], the layout LAMMPS
// expects (the first value is the part's length, itself included).
int FixWearscaleHistory::pack_restart(int i, double* buf) {
  const auto& c = contacts_[static_cast<std::size_t>(i)];
  buf[0] = static_cast<double>(2 + c.size());
  buf[1] = static_cast<double>(c.size());
  std::copy(c.begin(), c.end(), buf + 2);
  return 2 + static_cast<int>(c.size());
}

void FixWearscaleHistory::unpack_restart(int nlocal, int nth) {
  double** extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; ++k) m += static_cast<int>(extra[nlocal][m]);
  const auto n = static_cast<std::size_t>(extra[nlocal][m + 1]);
  contacts_[static_cast<std::size_t>(nlocal)].assign(&extra[nlocal][m + 2], &extra[nlocal][m + 2] + n);
}

int FixWearscaleHistory::size_restart(int i) { return 2 + static_cast<int>(contacts_[static_cast<std::size_t>(i)].size()); }

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
