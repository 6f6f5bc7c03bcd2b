#pragma once
// Running the LAMMPS program `lmp` as a subprocess: finding it, asking its
// version, and running one input deck in a run folder (stdout and stderr to
// stdout.txt there, LAMMPS' own log to log.lammps), through
// `mpirun --allow-run-as-root -np N` when more than one MPI rank is asked
// for and mpirun exists. A failed run (non-zero exit, an "ERROR" line) is a
// NumericalError naming the run folder and LAMMPS' error line.
//
// From a rank of an MPI job (wearscale itself under mpirun or srun) lmp and
// its mpirun start a job of their own: the child's environment drops the
// launcher's variables (OMPI_*, PMIX_*, PMI_*, SLURM_*, ...), which would make
// lmp's MPI_Init join the enclosing job, and such an mpirun does not bind.
// Every mpirun of lmp yields idle cores (mpi_yield_when_idle): on shared
// cores polling ranks slow each other down a hundredfold.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace wearscale::md {

/// The lmp executable: `requested` if given (a path, or a name searched on
/// PATH), else `lmp` on PATH. InputError saying "apt-get install lammps" if
/// it is not found or not executable.
std::filesystem::path find_lmp(const std::string& requested = {});

/// The LAMMPS version line of `lmp -h`, e.g. "29 Sep 2021 - Update 2".
/// Remembered per executable (path, size, modification time) in
/// `<cache_dir>/lmp-version/`, so a cached study never starts lmp.
/// NumericalError if lmp does not run or prints no version.
std::string lammps_version(const std::filesystem::path& lmp, const std::filesystem::path& cache_dir);

struct LammpsJob {
  std::filesystem::path lmp;       ///< from find_lmp()
  int ranks = 1;                   ///< > 1: run through mpirun if it exists
  std::filesystem::path run_dir;   ///< working folder, holds the deck
  std::string input = "in.lammps"; ///< deck file name inside run_dir
  std::string label;               ///< for messages ("Si shear test at 10 GPa")
};

struct LammpsRunInfo {
  double wall_seconds = 0.0;
  int ranks = 1;                   ///< ranks actually used (1 if mpirun is missing)
  std::vector<std::string> command;
};

/// This process is a rank of an MPI job (a launcher's variables are set).
bool is_mpi_rank();

/// The environment lmp and its mpirun get: this process's, less a launcher's
/// variables when this process is a rank of an MPI job (see above).
std::vector<std::string> child_environment();

/// The command line of a job (mpirun … lmp -in … -log log.lammps).
std::vector<std::string> lammps_command(const LammpsJob& job, int& ranks_used);

/// Runs the job and waits; `poll` (if set) is called about 4 times a second
/// while lmp runs (progress). NumericalError on failure (see above), with
/// the error line from stdout.txt / log.lammps.
LammpsRunInfo run_lammps(const LammpsJob& job, const std::function<void()>& poll = {});

/// The first LAMMPS "ERROR" line of a run folder's output, or "".
std::string lammps_error_line(const std::filesystem::path& run_dir);

}  // namespace wearscale::md
