#pragma once
// The initial roughness of the pin and the disc of [scale.macro] (pin_surface,
// disc_surface): a measured topography file or a generated self-affine surface,
// on the grid the pin-on-disc model stores the surface on.
#include <string>
#include <vector>

#include "wearscale/core/grid.hpp"
#include "wearscale/io/config.hpp"

namespace wearscale::coupling {

/// Heights [m] on `target` (grid order, index i·ny + j), and what they are.
struct InitialSurface {
  std::vector<double> heights;
  std::string description;
};

/// The surface of key `key` of `macro` on `target`, whose cells are square (the
/// pin's window: n × n over L; the resolved track's strip: n × track cells over
/// L × L_track). `window` is L, the unit of the wavenumbers k (k = L/λ).
///
/// A file (`key = "file"` or `key = { file, dataset, missing, level }`): any format
/// the topography readers take, with its units; it must cover the target (at least
/// lx × ly; its first lx × ly from its origin are used) and be sampled at least as
/// finely as the target's cells. Each target cell takes the area-weighted mean of
/// the file's samples over it (each sample standing for the dx × dy cell from its
/// point; equal sampling copies the samples), then the least-squares plane
/// (level = "plane", default) or the mean (level = "mean") is removed.
///
/// Generated (`key = { hurst, k_l | lambda_l, k_r | lambda_r, k_s | lambda_s, seed,
/// hprime_rms | h_rms | sa }`): bem::generate_surface on the target (the PSD of Fig. 1.3
/// with k on the target's reference length), rescaled to the target measure, mean removed.
/// InputError naming the key, its value and the allowed range for anything else.
InitialSurface read_initial_surface(const Config& macro, const std::string& key, const Grid2D& target, double window);

}  // namespace wearscale::coupling
