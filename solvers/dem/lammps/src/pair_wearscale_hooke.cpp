#include "pair_wearscale_hooke.hpp"

#include "atom.h"
#include "error.h"
#include "memory.h"
#include "pair_wearscale_loop.hpp"
#include "utils.h"
#include "wearscale/dem/hooke_kernel.hpp"

namespace wearscale::dem::lammps {

using namespace LAMMPS_NS;

PairWearscaleHooke::PairWearscaleHooke(LAMMPS* instance) : PairWearscale(instance) { set_touching_only(true); }

void PairWearscaleHooke::settings(int narg, char** arg) {
  if (narg != 5) error->all(FLERR, std::string("Illegal pair_style wearscale/hooke: k_N k_T gamma_N gamma_T mu"));
  k_n_ = utils::numeric(FLERR, arg[0], false, lmp);
  k_t_ = utils::numeric(FLERR, arg[1], false, lmp);
  gamma_n_ = utils::numeric(FLERR, arg[2], false, lmp);
  gamma_t_ = utils::numeric(FLERR, arg[3], false, lmp);
  friction_ = utils::numeric(FLERR, arg[4], false, lmp);
  if (!(k_n_ > 0.0) || !(k_t_ > 0.0) || !(gamma_n_ >= 0.0) || !(gamma_t_ >= 0.0) || !(friction_ >= 0.0))
    error->all(FLERR, std::string("Illegal pair_style wearscale/hooke: k_N, k_T > 0 and gamma_N, gamma_T, mu >= 0"));
}

void PairWearscaleHooke::coeff(int narg, char**) {
  if (narg != 2) error->all(FLERR, std::string("Incorrect args for pair coefficients: pair_coeff * *"));
  if (!allocated) {
    allocated = 1;
    const int n = atom->ntypes;
    memory->create(setflag, n + 1, n + 1, "pair:setflag");
    memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  }
  for (int i = 1; i <= atom->ntypes; ++i)
    for (int j = i; j <= atom->ntypes; ++j) setflag[i][j] = 1;
}

void PairWearscaleHooke::compute(int eflag, int vflag) {
  // gran/hooke/history's arithmetic: the kernel of wearscale's HookeLaw (hooke_kernel.hpp).
  struct Law {
    HookeSprings springs;
    PairForce contact(std::size_t, const PairState& s, const double* hist, double* updated, double dt,
                      bool advance) const {
      return hooke_contact(springs, s, hist, updated, dt, advance);
    }
  };
  loop(Law{{k_n_, k_t_, gamma_n_, gamma_t_, friction_}}, eflag, vflag);
}

}  // namespace wearscale::dem::lammps
