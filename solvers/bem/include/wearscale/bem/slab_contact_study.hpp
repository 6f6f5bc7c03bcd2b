#pragma once
// The contact study of a case ([contact], see contact_study.hpp) on the ranks
// of an MPI job (`mpirun -np P wearscale contact ...`): the fields in slabs of
// rows over the ranks (SlabHalfSpace, FFTW-MPI; memory per rank ≈ 1/P of the
// serial study's), the rough surface generated in slabs (the serial surface
// for the seed), the serial solver on them (the same iterations and answer).
// Rank 0 gathers the fields and writes the serial study's files when the grid
// has at most slab_gather_limit points; above, it writes the headline figures
// only (the serial HDF5 library cannot write collectively) and says so.
//
// Distributed so far: frictionless, periodic contact of a generated rough
// surface and/or a sphere. Refused with an InputError naming the key (the same
// on every rank, before any work): contact.friction other than "none",
// contact.boundary = "free", contact.surface (a measured file).
#include <cstddef>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "wearscale/core/config.hpp"

namespace wearscale::bem {

/// Grids above this many points are not gathered on rank 0 (8 B per point and field).
inline constexpr std::size_t slab_gather_limit = std::size_t{4096} * 4096;

/// Every rank calls it with the same case (collective). Returns what
/// run_contact_study returns on rank 0, null on the other ranks (which write nothing).
nlohmann::json run_slab_contact_study(const Config& config, const std::filesystem::path& output_dir);

}  // namespace wearscale::bem
