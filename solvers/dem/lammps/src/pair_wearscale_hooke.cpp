#include "pair_wearscale_hooke.hpp"

#include <cmath>

#include "atom.h"
#include "error.h"
#include "memory.h"
#include "pair_wearscale_loop.hpp"
#include "utils.h"
#include "wearscale/dem/coulomb_cap.hpp"

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
  // gran/hooke/history's arithmetic, as wearscale's HookeLaw writes it.
  struct Law {
    double k_n, k_t, gamma_n, gamma_t, friction;
    PairResult contact(const PairKinematics& s, const double* hist, double* updated, double dt, bool advance,
                       long long) const {
      PairResult out;
      const double r2 = dot(s.d, s.d);
      const double radsum = s.ri + s.rj;
      const bool touching = !(r2 >= radsum * radsum);
      const Vec3 del = -s.d;  // x_i − x_j
      const double r = std::sqrt(r2);
      const double rinv = 1.0 / r;
      const double rsqinv = rinv * rinv;
      const double vnnr = dot(s.v, del);
      const Vec3 vt = s.v - del * (vnnr * rsqinv);
      const Vec3 wr = s.w * rinv;
      const double meff = s.mi * s.mj / (s.mi + s.mj);
      const double damp = meff * gamma_n * vnnr * rsqinv;
      const double ccel = k_n * (radsum - r) * rinv - damp;
      const Vec3 vtr = vt + cross(del, wr);
      Vec3 shear{hist[0], hist[1], hist[2]};
      if (advance) shear += vtr * dt;
      const bool sheared = dot(shear, shear) != 0.0;
      if (advance) shear -= del * (dot(shear, del) * rsqinv);
      const double damp_t = meff * gamma_t;
      Vec3 fs = -(k_t * shear + damp_t * vtr);
      cap_tangential(fs, shear, vtr * (damp_t / k_t), friction * std::fabs(ccel * r), sheared);  // Coulomb cap
      // Apart: no force, no history. By components (a whole-struct copy stops the vectoriser).
      updated[0] = touching ? shear.x : 0.0;
      updated[1] = touching ? shear.y : 0.0;
      updated[2] = touching ? shear.z : 0.0;
      const Vec3 total = del * ccel + fs, n = s.d * rinv;
      out.force = {total.x, total.y, total.z};
      out.tangential = {fs.x, fs.y, fs.z};
      out.normal = {n.x, n.y, n.z};
      out.active = touching;
      return out;
    }
  };
  loop(Law{k_n_, k_t_, gamma_n_, gamma_t_, friction_}, eflag, vflag);
}

}  // namespace wearscale::dem::lammps
