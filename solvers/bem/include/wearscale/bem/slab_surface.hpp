#pragma once
// Rough surfaces made and measured in slabs over the ranks of an MPI job: each
// rank draws the modes of its rows of the spectrum from their places in the
// seed's random stream (rough_spectrum), transforms them with FFTW-MPI and
// keeps its rows of the heights, the same surface as generate_surface for the
// seed (to round-off of the transforms). Collective calls.
#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/core/slab_fft.hpp"

namespace wearscale::bem {

/// This rank's rows (fft.first_row(), fft.rows()) of generate_surface(spec).
RealField generate_surface_slab(const RoughSurfaceSpec& spec, SlabFFT& fft);
/// The same, rescaled so that `measure` over the whole surface equals `target`.
RealField generate_surface_slab(const RoughSurfaceSpec& spec, RoughnessMeasure measure, double target, SlabFFT& fft);

/// roughness(h, measure) of the surface on `grid` whose rows `slab` holds on each rank.
double roughness_slab(const RealField& slab, const Grid2D& grid, RoughnessMeasure measure, SlabFFT& fft);

}  // namespace wearscale::bem
