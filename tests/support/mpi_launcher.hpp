#pragma once
// The launcher of the MPI tests: `mpirun -np P` as CMake found it
// (WEARSCALE_MPIRUN: --allow-run-as-root --oversubscribe), for run_cli.
#include <string>

/// `mpirun … -np ranks`, or nothing for ranks = 0 (the program started on its own).
inline std::string mpi_launcher(int ranks) {
  return ranks == 0 ? std::string() : std::string(WEARSCALE_MPIRUN) + " -np " + std::to_string(ranks);
}
