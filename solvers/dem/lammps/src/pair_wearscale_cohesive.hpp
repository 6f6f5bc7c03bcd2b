#pragma once
// pair_style wearscale/cohesive: the thesis' reversible cohesive pair force
// of §6.1 ((6.2)-(6.5), parameters (6.49)-(6.62) from each pair's material
// and radii, as wearscale's CohesiveLaw) as a LAMMPS pair style.
//
//   pair_style wearscale/cohesive [history kept|touching] [cohesion yes|no] [tangential yes|no]
//   pair_coeff I J E nu sigma_mN sigma_mT gamma s eta
//
// history: `kept` (default) carries every pair's tangential history over
// neighbour rebuilds, per periodic image (what (6.4) defines); `touching`
// only that of pairs touching at the rebuild, as LAMMPS' fix neigh/history
// does for a granular style without beyond_contact (the thesis' runs).
// Needs atom_style sphere, comm_modify vel yes and newton_pair on (the default).
#include <vector>

#include "pair_wearscale.hpp"
#include "wearscale/dem/cohesive_law.hpp"

namespace wearscale::dem::lammps {

class PairWearscaleCohesive final : public PairWearscale {
 public:
  explicit PairWearscaleCohesive(LAMMPS_NS::LAMMPS* lmp);
  ~PairWearscaleCohesive() override;
  void settings(int narg, char** arg) override;
  void coeff(int narg, char** arg) override;
  void compute(int eflag, int vflag) override;

 private:
  double reach(double max_radius) const override;
  void prepare_pairs() override;
  void allocate();
  const CohesiveMaterial& material(int type_i, int type_j) const {
    return materials_[static_cast<std::size_t>(type_i * (atom_types_ + 1) + type_j)];
  }

  bool cohesion_ = true, tangential_ = true;
  int atom_types_ = 0;
  std::vector<CohesiveMaterial> materials_;  // (types + 1)² by type pair
  // The listed pairs' parameters: one set when every atom of this rank has
  // the same type, radius and mass, else one per list entry.
  bool uniform_ = false;
  CohesivePair uniform_pair_;
  std::vector<CohesivePair> pairs_;
};

}  // namespace wearscale::dem::lammps
