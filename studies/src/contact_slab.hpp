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
// The case is read by read_contact_case (contact_case.hpp), on every rank
// alike: a file of fewer rows than ranks is refused there, naming the key.
#include "contact_case.hpp"

namespace wearscale::studies {

/// Solves the case on every rank (collective). Rank 0 passes its context and
/// writes; the other ranks pass nullptr and write nothing. A measured surface
/// is freed once each rank has taken its rows.
void run_slab_contact(const Config& config, ContactCase c, coupling::RunContext* context);

}  // namespace wearscale::studies
