#pragma once
// What wearscale's LAMMPS pair styles share (wearscale/cohesive,
// wearscale/hooke): a tangential history of three doubles for every entry of
// the half neighbour list, carried over rebuilds by FixWearscaleHistory (per
// partner and per periodic image, as wearscale's own neighbour list does),
// the pair loop with the law's force inlined (pair_wearscale_loop.hpp), and
// the per-atom virial W_i = ½ Σ_j (x_j − x_i) ⊗ f_ij the patch tests measure.
//
// Newton's third law is on (LAMMPS' default): each pair is computed once, on
// one rank, the force and torque on a ghost atom travel back to its owner
// with LAMMPS' reverse communication, and so do the per-atom virials (here)
// and the histories stored under a ghost (FixWearscaleHistory).
#include <vector>

#include "pair.h"
#include "wearscale/dem/vec3.hpp"

namespace wearscale::dem::lammps {

class FixWearscaleHistory;

class PairWearscale : public LAMMPS_NS::Pair {
 public:
  explicit PairWearscale(LAMMPS_NS::LAMMPS* lmp);
  ~PairWearscale() override;

  void init_style() override;
  double init_one(int i, int j) override;
  double memory_usage() override;
  int pack_reverse_comm(int n, int first, double* buf) override;
  void unpack_reverse_comm(int n, int* list, double* buf) override;

  /// Keep the per-atom virial (virial()) at every force evaluation.
  void set_track_virial(bool on) { track_virial_ = on; }
  /// The per-atom virial of the local atoms (their ghosts' shares added), 6 a
  /// row (xx yy zz xy xz yz).
  const std::vector<double>& virial() const { return virial_; }
  /// Carry a stored history over a rebuild only to pairs touching then (LAMMPS'
  /// own transfer for granular styles without beyond_contact); else every one.
  void set_touching_only(bool on) { touching_only_ = on; }
  bool touching_only() const { return touching_only_; }

  // The history's carry-over, called by FixWearscaleHistory.
  /// Whether the histories in hand belong to the list in hand.
  bool loaded() const { return loaded_; }
  /// Each listed pair with a history: under i and under j (a ghost's records
  /// then go to its owner), keyed by the partner's tag and the separation
  /// (which periodic image it is).
  void store_histories(FixWearscaleHistory& fix) const;
  /// The new list's pairs take the histories stored for them; `setup`: the
  /// rebuild at the start of a run, which carries every one.
  void load_histories(const FixWearscaleHistory& fix, bool setup);

 protected:
  /// The interaction range beyond contact (δ_f of the widest pair; 0: contact only).
  virtual double reach(double max_radius) const = 0;
  /// Per-pair parameters once a list is loaded (the cohesive law's (6.53)-(6.61)).
  virtual void prepare_pairs() {}
  /// The pair loop with `law.contact(k, state, history, updated, dt,
  /// advance)` inlined, the law of wearscale's own pair loop (a PairState in,
  /// a PairForce out: dem/contact_law.hpp; pair_wearscale_loop.hpp).
  template <class Law>
  void loop(const Law& law, int eflag, int vflag);
  /// The largest radius of any atom on any rank.
  double max_radius() const;
  /// The list's entries (all rows), and entry k's row start.
  long long entries() const { return first_.empty() ? 0 : first_.back(); }

  std::vector<double> history_;   // 3 per list entry; row ii's entries from first_[ii]
  std::vector<long long> first_;  // inum + 1 row offsets
  std::vector<double> virial_;    // 6 per local and ghost atom
  FixWearscaleHistory* fix_ = nullptr;
  bool track_virial_ = false;
  bool touching_only_ = false;
  bool loaded_ = false;
};

}  // namespace wearscale::dem::lammps
