#pragma once
// The tangential histories of wearscale's LAMMPS pair styles between two
// neighbour lists: at a rebuild (pre_exchange) and at the end of a run every listed pair with a
// history is stored under both its atoms (a ghost's records go to its
// owner by reverse communication), keyed by the partner's tag and the
// separation vector x_partner − x_atom; the records travel with their atom
// to whichever rank owns it next and into restart files; once the new list
// is built (post_neighbor) each of its pairs takes the record of the same
// partner at the nearest separation. Periodic images of one partner lie a
// box length apart, so each image keeps its own history (a thin periodic
// cell, where LAMMPS' fix neigh/history keeps one per partner). Written
// against the public fix.h (Debian's liblammps-dev has no fix_neigh_history.h).
//
// With the touching-only transfer the rebuilds that drop histories are
// wearscale's: when a particle has moved more than half the skin since the
// last such rebuild (unwrapped, so a run split in chunks, each of which
// LAMMPS starts with a rebuild of its own, drops them as one run would). This
// fix asks LAMMPS for those rebuilds; the others carry every history.
#include <array>
#include <vector>

#include "fix.h"

namespace wearscale::dem::lammps {

class PairWearscale;

class FixWearscaleHistory : public LAMMPS_NS::Fix {
 public:
  /// One stored contact: the partner's tag, the separation x_partner − x_atom
  /// at the store, the history.
  static constexpr int record = 7;

  FixWearscaleHistory(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);
  ~FixWearscaleHistory() override;
  int setmask() override;
  void set_pair(PairWearscale* pair) { pair_ = pair; }

  void setup_pre_exchange() override;
  void post_integrate() override;
  void pre_exchange() override;
  void post_run() override;
  void setup_post_neighbor() override;
  void post_neighbor() override;

  void grow_arrays(int nmax) override;
  void copy_arrays(int i, int j, int delflag) override;
  int pack_exchange(int i, double* buf) override;
  int unpack_exchange(int nlocal, double* buf) override;
  int pack_reverse_comm_size(int n, int first) override;
  int pack_reverse_comm(int n, int first, double* buf) override;
  void unpack_reverse_comm(int n, int* list, double* buf) override;
  int pack_restart(int i, double* buf) override;
  void unpack_restart(int nlocal, int nth) override;
  int size_restart(int i) override;
  int maxsize_restart() override;
  double memory_usage() override;

  /// The records of atom i (record doubles each): local atoms' between a
  /// store and a load, a ghost's on their way to its owner.
  std::vector<std::vector<double>>& contacts() { return contacts_; }
  const std::vector<std::vector<double>>& contacts() const { return contacts_; }

 private:
  void store();
  void refresh_exchange_size();
  void set_reference();

  PairWearscale* pair_ = nullptr;
  std::vector<std::vector<double>> contacts_;
  // Per local atom: its unwrapped position at the last rebuild that dropped
  // histories (touching-only transfer), and whether it holds one.
  std::vector<std::array<double, 3>> reference_;
  std::vector<char> referenced_;
  bool stored_ = false;  // contacts_ hold the histories; the pair's list has not been rebuilt since
  bool due_ = false;     // the rebuild asked for this step drops histories
};

}  // namespace wearscale::dem::lammps
