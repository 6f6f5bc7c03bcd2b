#include "pair_wearscale_cohesive.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "atom.h"
#include "error.h"
#include "memory.h"
#include "neigh_list.h"
#include "pair_wearscale_loop.hpp"
#include "utils.h"
#include "wearscale/dem/cohesive_kernel.hpp"

namespace wearscale::dem::lammps {

using namespace LAMMPS_NS;

namespace {

// The cohesive force of §6.1 on one pair, (6.2)-(6.5): the kernel of
// wearscale's CohesiveLaw (cohesive_kernel.hpp), its switches and the layout
// of the pairs' parameters fixed per loop.
template <bool Uniform, bool Cohesion, bool Tangential>
struct CohesiveContact {
  CohesivePair uniform;        // Uniform: every pair's parameters
  const CohesivePair* pairs;   // else per list entry

  PairForce contact(std::size_t k, const PairState& s, const double* hist, double* updated, double dt,
                    bool advance) const {
    const CohesivePair p = Uniform ? uniform : pairs[k];
    return cohesive_contact<Cohesion, Tangential>(p, s, hist, updated, dt, advance);
  }
};

}  // namespace

PairWearscaleCohesive::PairWearscaleCohesive(LAMMPS* instance) : PairWearscale(instance) {}

PairWearscaleCohesive::~PairWearscaleCohesive() = default;

void PairWearscaleCohesive::settings(int narg, char** arg) {
  auto yes_no = [&](const char* key, const char* value) {
    if (std::strcmp(value, "yes") == 0) return true;
    if (std::strcmp(value, "no") == 0) return false;
    error->all(FLERR, std::string("Illegal pair_style wearscale/cohesive ") + key + " " + value + ": yes or no");
  };
  for (int a = 0; a + 1 < narg; a += 2) {
    if (std::strcmp(arg[a], "history") == 0) {
      if (std::strcmp(arg[a + 1], "kept") == 0)
        set_touching_only(false);
      else if (std::strcmp(arg[a + 1], "touching") == 0)
        set_touching_only(true);
      else
        error->all(FLERR, std::string("Illegal pair_style wearscale/cohesive history ") + arg[a + 1] + ": kept or touching");
    } else if (std::strcmp(arg[a], "cohesion") == 0) {
      cohesion_ = yes_no("cohesion", arg[a + 1]);
    } else if (std::strcmp(arg[a], "tangential") == 0) {
      tangential_ = yes_no("tangential", arg[a + 1]);
    } else {
      error->all(FLERR, std::string("Illegal pair_style wearscale/cohesive keyword ") + arg[a]);
    }
  }
  if (narg % 2 != 0) error->all(FLERR, std::string("Illegal pair_style wearscale/cohesive: keyword without a value"));
}

void PairWearscaleCohesive::allocate() {
  allocated = 1;
  atom_types_ = atom->ntypes;
  const int n = atom_types_;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  for (int i = 1; i <= n; ++i)
    for (int j = i; j <= n; ++j) setflag[i][j] = 0;
  materials_.assign(static_cast<std::size_t>((n + 1) * (n + 1)), CohesiveMaterial{});
}

void PairWearscaleCohesive::coeff(int narg, char** arg) {
  if (narg != 9) error->all(FLERR, std::string("Incorrect args for pair coefficients: I J E nu sigma_mN sigma_mT gamma s eta"));
  if (!allocated) allocate();
  int ilo = 0, ihi = 0, jlo = 0, jhi = 0;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  CohesiveMaterial m;
  m.name = "pair_coeff";
  m.young = utils::numeric(FLERR, arg[2], false, lmp);
  m.poisson = utils::numeric(FLERR, arg[3], false, lmp);
  m.tensile_strength = utils::numeric(FLERR, arg[4], false, lmp);
  m.shear_strength = utils::numeric(FLERR, arg[5], false, lmp);
  m.surface_energy = utils::numeric(FLERR, arg[6], false, lmp);
  m.scaling_exponent = utils::numeric(FLERR, arg[7], false, lmp);
  m.restitution = utils::numeric(FLERR, arg[8], false, lmp);
  m.density = 1.0;  // masses are the atoms' own
  if (const std::string why = why_not_modelled(m); !why.empty())
    error->all(FLERR, std::string("Incorrect args for pair coefficients: ") + why);
  int count = 0;
  for (int i = ilo; i <= ihi; ++i)
    for (int j = std::max(jlo, i); j <= jhi; ++j) {
      materials_[static_cast<std::size_t>(i * (atom_types_ + 1) + j)] = m;
      materials_[static_cast<std::size_t>(j * (atom_types_ + 1) + i)] = m;
      setflag[i][j] = 1;
      ++count;
    }
  if (count == 0) error->all(FLERR, std::string("Incorrect args for pair coefficients"));
}

double PairWearscaleCohesive::reach(double max_radius) const {
  if (!cohesion_) return 0.0;
  double reach = 0.0;
  for (int i = 1; i <= atom_types_; ++i)
    for (int j = i; j <= atom_types_; ++j) {
      if (!setflag[i][j]) continue;
      const CohesiveMaterial& m = material(i, j);
      // δ_f is constant below d_c and grows as (r_i + r_j)^(1−s) above it (6.57).
      reach = std::max({reach, fracture_separation(m, 2.0 * max_radius), 4.0 * m.surface_energy / m.tensile_strength});
    }
  return reach;
}

void PairWearscaleCohesive::prepare_pairs() {
  const int* type = atom->type;
  const double* radius = atom->radius;
  const double* rmass = atom->rmass;
  const int n = atom->nlocal + atom->nghost;
  uniform_ = true;
  for (int i = 1; i < n && uniform_; ++i)
    uniform_ = type[i] == type[0] && radius[i] == radius[0] && rmass[i] == rmass[0];
  if (uniform_) {
    if (n > 0) uniform_pair_ = cohesive_pair(material(type[0], type[0]), radius[0], radius[0], rmass[0], rmass[0]);
    std::vector<CohesivePair>().swap(pairs_);
    return;
  }
  pairs_.resize(static_cast<std::size_t>(entries()));
  for (int ii = 0; ii < list->inum; ++ii) {
    const int i = list->ilist[ii];
    const int* jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; ++jj) {
      const int j = jlist[jj] & NEIGHMASK;
      pairs_[static_cast<std::size_t>(first_[static_cast<std::size_t>(ii)] + jj)] =
          cohesive_pair(material(type[i], type[j]), radius[i], radius[j], rmass[i], rmass[j]);
    }
  }
}

void PairWearscaleCohesive::compute(int eflag, int vflag) {
  // The switches and the parameters' layout, once per evaluation.
  auto run = [&]<bool Cohesion, bool Tangential>() {
    if (uniform_)
      loop(CohesiveContact<true, Cohesion, Tangential>{uniform_pair_, pairs_.data()}, eflag, vflag);
    else
      loop(CohesiveContact<false, Cohesion, Tangential>{uniform_pair_, pairs_.data()}, eflag, vflag);
  };
  if (cohesion_ && tangential_)
    run.template operator()<true, true>();
  else if (cohesion_)
    run.template operator()<true, false>();
  else if (tangential_)
    run.template operator()<false, true>();
  else
    run.template operator()<false, false>();
}

}  // namespace wearscale::dem::lammps
