#pragma once
// The LAMMPS engine of the DEM drivers (engine.hpp): the system wearscale
// built, integrated by LAMMPS (Debian's liblammps, linked as a library) with
// wearscale's contact laws as LAMMPS pair styles (wearscale/cohesive,
// wearscale/hooke), its histories per periodic image (fix
// wearscale/history) and its walls and integrator (fix wearscale/verlet),
// over LAMMPS' domain decomposition.
//
// Alone (a process of its own, or a task of the farm) an engine is a LAMMPS
// instance on this process (MPI_COMM_SELF). Under `mpirun -np P`, while rank
// 0 holds a LammpsServedRun, the engines it makes span every rank of the job:
// the other ranks run serve_lammps_engines(), which executes each of rank
// 0's calls with it; rank 0 alone holds the particles the drivers read
// (gathered after each call) and writes the outputs.
#include <string>

namespace wearscale::dem {

/// Makes "lammps" known to make_engine() (engine.hpp). Idempotent.
void register_lammps_engine();

/// The LAMMPS library linked, e.g. "LAMMPS 20210929".
std::string lammps_engine_version();

/// Rank 0's side of a run whose LAMMPS engines span every rank of an MPI job
/// (mpi::size() > 1): collective with serve_lammps_engines() on the others
/// (both duplicate the job's communicator). Its end releases them. Serial or
/// on one rank: nothing.
class LammpsServedRun {
 public:
  LammpsServedRun();
  ~LammpsServedRun();
  LammpsServedRun(const LammpsServedRun&) = delete;
  LammpsServedRun& operator=(const LammpsServedRun&) = delete;
  /// One lives on this rank, with ranks to serve it.
  static bool active();

 private:
  bool serving_ = false;
};

/// The other ranks of such a job: run the engines rank 0 makes, call by call,
/// until its LammpsServedRun ends. Waits without spinning a core.
void serve_lammps_engines();

/// Whether LAMMPS engines may run on several threads of this process at once
/// (MPI initialised with MPI_THREAD_MULTIPLE, or not yet: the engine then
/// initialises it so). Under mpirun (funnelled MPI) one at a time, on the
/// main thread.
bool lammps_engines_on_threads();

}  // namespace wearscale::dem
