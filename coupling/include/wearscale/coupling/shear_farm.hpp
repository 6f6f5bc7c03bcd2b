#pragma once
// The LAMMPS runs of a shear study (md::run_shear_study: the SiO2 quench,
// then the pressure points) spread over the ranks of an MPI job by the task
// farm (core/task_farm.hpp), rank 0 gathering what each run did; one rank
// (serial, a build without MPI, or a task of an enclosing farm): in order,
// here. Each point's figures are read back from its cache entry, so the
// study is the same whichever rank ran which point.
#include <string>

#include "wearscale/md/shear_study.hpp"

namespace wearscale::coupling {

/// The map for md::run_shear_study. Collective under mpirun: every rank calls
/// the study with it. A run that fails (NumericalError, InputError) ends the
/// study on every rank together (mpi::TasksFailed, exit status 1) once the
/// other runs are done, rank 0 naming the failed pressures' errors.
md::RunMap farmed_shear_runs(std::string label);

/// The map for md::run_shear_study in a pipeline that rank 0 runs while the
/// other ranks serve it (mpi::ServedRun): each run travels as (material, map
/// call, index) to whichever rank asks, which runs that one run of the
/// material's registered study. Rank 0 gets every run's text; a failed run
/// ends the scale (its NumericalError or InputError), as serially.
md::RunMap served_shear_runs(const std::string& material, std::string label);

/// The study of `material` as served runs see it: every rank registers it
/// when its pipeline is prepared (the molecular/lammps backend's constructor).
void register_served_shear_study(const std::string& material, const md::ShearTestSpec& spec);

}  // namespace wearscale::coupling
