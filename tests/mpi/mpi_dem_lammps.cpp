// The DEM drivers on the LAMMPS engine over the ranks of `mpirun -np P`: one
// run spread over every rank by LAMMPS' domain decomposition (rank 0 drives
// it, the others serve its calls), against the same driver on wearscale's
// own engine (on rank 0). Reduced sizes; exit 0 when the figures agree.
//   mpirun -np P mpi_dem_lammps patch | junction-kept | junction-touching | rough-shear | resume
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "wearscale/core/mpi.hpp"
#include "wearscale/dem/engine.hpp"
#include "wearscale/dem/junction_strength.hpp"
#include "wearscale/dem/lammps_engine.hpp"
#include "wearscale/dem/patch_test.hpp"
#include "wearscale/dem/rough_shear.hpp"
#include "wearscale/materials/material.hpp"

using namespace wearscale;
using namespace wearscale::dem;

namespace {

bool within(const char* what, double lammps, double house, double bound) {
  const double relative = std::fabs(lammps - house) / std::fabs(house);
  std::printf("%s: lammps %.6g, wearscale %.6g, difference %.3g %% (bound %.3g %%) on %d rank(s)\n", what, lammps, house,
              100.0 * relative, 100.0 * bound, mpi::size());
  return relative <= bound;
}

bool patch() {
  PatchTestSpec s;
  s.material = patch_test_targets();
  s.material.poisson = 0.1;
  s.d0 = 90.0;
  s.length = 15.0;
  s.strengths = false;
  const auto house = run_patch_test(s);
  s.engine = "lammps";
  const auto lmp = run_patch_test(s);
  return within("E", lmp.young, house.young, 0.01) & within("nu", lmp.poisson, house.poisson, 0.01);
}

// The full-contact cell of Fig. 7.2 (D = L, p_N = 0), slid past its first slip.
JunctionStrengthSpec full_contact(bool touching) {
  JunctionStrengthSpec s;
  s.top = s.bottom = cohesive_material(materials::silica(), 0.5);
  s.cell.d0 = 1.5e-9;
  s.contact_ratio = 1.0;
  s.velocity = 50.0;
  s.settle_distance = 0.02;
  s.sliding_distance = 0.4;
  s.history_of_touching_pairs_only = touching;
  return s;
}

bool junction(bool touching) {
  auto s = full_contact(touching);
  const auto house = run_junction_strength(s);
  s.engine = "lammps";
  const auto lmp = run_junction_strength(s);
  return within(touching ? "peak p_T (touching)" : "peak p_T (kept)", lmp.peak_tangential, house.peak_tangential, 0.03);
}

bool rough_shear() {
  RoughShearSpec s;
  s.cell.material = cohesive_material(materials::silica(), 0.5);
  s.cell.d0 = 3e-9;
  s.cell.box = {20 * 3e-9, 3.5 * 3e-9, 14 * 3e-9};
  s.cell.pressure = 0.5e9;
  s.cell.velocity = 100.0;
  s.cell.sliding_distance = 8 * 3e-9;
  s.cell.settle_distance = 3e-9;
  s.roughness = 0.04;
  const auto house = run_rough_shear(s);
  s.cell.engine = "lammps";
  const auto lmp = run_rough_shear(s);
  return within("mean mu", lmp.friction, house.friction, 0.05);
}

// A state saved halfway and restored into a system set up again continues
// bit for bit as the run that never stopped (same ranks).
bool resume() {
  auto s = full_contact(false);
  s.engine = "lammps";
  s.sliding_distance = 0.1;
  CheckpointState saved;
  long saved_at = 0;
  RunCheckpoints save;
  save.at_sample = [&](long step, const std::function<CheckpointState()>& make) {
    if (saved_at == 0 && step >= 1000) {
      saved = make();
      saved_at = step;
    }
  };
  const auto whole = run_junction_strength(s, {}, save);
  RunCheckpoints from;
  saved.origin = "the saved state";
  from.from = &saved;
  // The step the state holds (as the studies' checkpointer sets it).
  saved.step = saved_at;
  const auto resumed = run_junction_strength(s, {}, from);
  // And saving did not move the run off its course: the same bits as one that never saved.
  const auto plain = run_junction_strength(s);
  auto same_as = [&](const JunctionStrengthResult& r) {
    return whole.history.size() == r.history.size() &&
           std::memcmp(whole.history.data(), r.history.data(), whole.history.size() * sizeof(JunctionSample)) == 0;
  };
  const bool same = same_as(resumed), undisturbed = same_as(plain);
  std::printf("resumed at step %ld of %ld: %s; saving %s (last p_T %.17g / %.17g / %.17g) on %d rank(s)\n", saved_at,
              whole.steps, same ? "the same bits" : "DIFFERENT", undisturbed ? "changed nothing" : "CHANGED THE RUN",
              whole.history.back().tangential_force, resumed.history.back().tangential_force,
              plain.history.back().tangential_force, mpi::size());
  return same && undisturbed && saved_at > 0;
}

}  // namespace

int main(int argc, char** argv) {
  mpi::Session session(argc, argv);
  register_lammps_engine();
  if (argc != 2) {
    std::fprintf(stderr, "usage: mpi_dem_lammps patch|junction-kept|junction-touching|rough-shear|resume\n");
    return 2;
  }
  if (mpi::rank() != 0) {
    serve_lammps_engines();
    return 0;
  }
  bool ok = false;
  {
    const LammpsServedRun served;
    const std::string what = argv[1];
    if (what == "patch") ok = patch();
    else if (what == "junction-kept") ok = junction(false);
    else if (what == "junction-touching") ok = junction(true);
    else if (what == "rough-shear") ok = rough_shear();
    else if (what == "resume") ok = resume();
    else std::fprintf(stderr, "unknown case %s\n", argv[1]);
  }
  return ok ? 0 : 1;
}
