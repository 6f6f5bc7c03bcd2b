#pragma once
// The contact study on the ranks of an MPI job (`mpirun -np P wearscale
// contact CASE`): the fields in slabs of rows over the ranks (SlabHalfSpace,
// FFTW-MPI; memory per rank about 1/P of the serial study's), the rough
// surface drawn per slab from the seed's stream (the serial surface), the one
// Polonsky–Keer solver on them (the serial iterations and answer). Rank 0
// gathers height, pressure, gap and displacement and writes the serial study's
// files when the grid has at most `[run] gather_limit` points; above it no
// rank holds a whole field: rank 0 lays contact.h5 out on disk and every rank
// writes its own rows of the fields into it in place; the headline figures
// come from the slabs and the micro-contacts from each rank's clusters joined
// across the slabs' edges (find_clusters_slab): the same files.
//
// Distributed: periodic contact of a measured surface (contact.surface: every
// rank reads the file and keeps its rows), a generated rough surface and/or a
// sphere, frictionless (NormalContact on a SlabHalfSpace, or on a
// SlabFreeHalfSpace for contact.boundary = "free") or with Coulomb or Tresca
// friction (FrictionalContact on a SlabHalfSpace holding the whole tensor;
// the surface and subsurface stresses from the gathered tractions on rank 0,
// or above the gather limit from each rank's rows, SlabSubsurfaceStress).
// Crack initiation (4.25) per micro-contact is checked on each rank's rows,
// with the rows on either side from its neighbours (crack_initiation_slab).
// Refused (InputError naming the key, the same on every rank, before any
// work): a file of fewer rows than ranks.
#include <cstddef>
#include <optional>

#include "contact_case.hpp"

namespace wearscale::studies {

/// `[run] gather_limit` by default: grids above this many points are not
/// gathered on rank 0 (88 B a point there for the fields and micro-contacts).
inline constexpr std::size_t default_gather_limit = std::size_t{4096} * 4096;

/// `[run] gather_limit` (grid points, at least 1), read and checked: every
/// run reads it (the contact study's Study::read_run_limits), the slab study uses it.
long read_gather_limit(const Config& config);

/// A [contact] case the slabs can run, every key read and checked.
struct SlabCase {
  Grid2D grid;
  NormalCase normal;                     ///< frictionless (friction = "none")
  std::optional<FrictionalCase> friction;  ///< friction = "coulomb" | "tresca"
  RealField measured;  ///< contact.surface's heights, whole (empty: none); the slabs keep their rows
  std::optional<RoughCase> rough;
  double sphere_radius = 0.0;  ///< 0: no sphere
  bool measured_plans = true;  ///< FFTW MEASURE plans ([run] fft_planning, and from 512²)
  std::size_t gather_limit = default_gather_limit;  ///< [run] gather_limit: larger grids are written in place
};

/// Reads and checks the case (collective only through the InputError it may
/// throw alike on every rank); ends with config.reject_unknown_keys().
SlabCase read_slab_case(const Config& config);

/// Solves the case on every rank (collective). Rank 0 passes its context and
/// writes; the other ranks pass nullptr and write nothing. A measured surface
/// is freed once each rank has taken its rows.
void run_slab_contact(const Config& config, SlabCase slab, coupling::RunContext* context);

}  // namespace wearscale::studies
