// A LAMMPS executable with one extra pair style, gran/cohesive/history (the
// thesis' cohesive DEM law, chapter 6), linked against Debian's liblammps.
// Debian's LAMMPS has no PLUGIN package, so the style is entered into the
// pair-style map by hand before the input is read. The style's source is not
// part of wearscale: build.sh takes it from the thesis' public LAMMPS fork.
#include <mpi.h>

#include "force.h"
#include "input.h"
#include "lammps.h"
#include "pair_gran_cohesive_history.h"

using namespace LAMMPS_NS;

namespace {
Pair* make_cohesive(LAMMPS* lmp) { return new PairGranCohesiveHistory(lmp); }
}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  auto* lmp = new LAMMPS(argc, argv, MPI_COMM_WORLD);
  (*lmp->force->pair_map)["gran/cohesive/history"] = &make_cohesive;
  lmp->input->file();
  delete lmp;
  MPI_Finalize();
  return 0;
}
