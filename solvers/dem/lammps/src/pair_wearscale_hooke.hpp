#pragma once
// pair_style wearscale/hooke: the linear spring-dashpot with a Coulomb-capped
// tangential history of wearscale's HookeLaw (term by term what LAMMPS'
// gran/hooke/history computes) as a LAMMPS pair style on wearscale's pair
// history, so that the two engines run the benchmark law alike.
//
//   pair_style wearscale/hooke k_N k_T gamma_N gamma_T mu
//   pair_coeff * *
//
// Repulsion only: a pair's history lives while it touches.
#include "pair_wearscale.hpp"

namespace wearscale::dem::lammps {

class PairWearscaleHooke final : public PairWearscale {
 public:
  explicit PairWearscaleHooke(LAMMPS_NS::LAMMPS* lmp);
  void settings(int narg, char** arg) override;
  void coeff(int narg, char** arg) override;
  void compute(int eflag, int vflag) override;

 private:
  double reach(double) const override { return 0.0; }
  double k_n_ = 0.0, k_t_ = 0.0, gamma_n_ = 0.0, gamma_t_ = 0.0, friction_ = 0.0;
};

}  // namespace wearscale::dem::lammps
