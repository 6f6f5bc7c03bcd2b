#pragma once
// The wear maps of rough contacts (§5.3, Fig. 5.6–5.7): the numerical
// detachment model over a grid of normalized loads p̃_N (5.1) and critical
// diameters d*/L, on several random surfaces (seeds), averaged with their
// standard deviation. A pixel is invalid (crossed in Fig. 5.6) when its
// particles are comparable to the simulated window.
//
// Work: the BEM contact depends on (seed, p̃_N) only and is solved once for
// the whole d* axis (warm-started along the loads); the candidates, the
// displacement of the full loading and the candidates' self-energies are
// shared by the d* values, which run in parallel. The surfaces are
// independent: rough_wear_map_surface() computes one, combine_surfaces()
// averages them (an ensemble may run its surfaces on different processes and
// get the same bits as rough_wear_map()).
#include <cstdint>
#include <functional>
#include <vector>

#include "wearscale/wear/detachment.hpp"
#include "wearscale/wear/micro_contact_map.hpp"

namespace wearscale::wear {

struct RoughWearMapSpec {
  RoughContactSpec surface;                 ///< n, H, q_l, q_s, ν (§5.3: 512, 0.8, 8, n/8)
  std::vector<std::uint64_t> seeds = {1, 2, 3, 4, 5};
  std::vector<double> loads;                ///< p̃_N, increasing
  std::vector<double> critical_diameters;   ///< d*/L
  double tensile_strength = 1.0;            ///< σ_m / σ_j (4.25)
  double spot = 0.05;                       ///< crack_sites: fraction of each micro-contact's peak edge stress
  double invalid_diameter = 0.25;           ///< a pixel is invalid when the mean largest particle ≥ this × L
  DetachmentOptions options;                ///< method, cumulative balance (options.parallel is set per level)
};

/// InputError naming the parameter, its value and the allowed range.
void validate(const RoughWearMapSpec& spec);

/// One (p̃_N, d*/L) pixel over the seeds.
struct WearMapPixel {
  double load = 0.0, critical_diameter = 0.0;  ///< p̃_N, d*/L
  double count_mean = 0.0, count_sd = 0.0;     ///< number of particles
  double volume_mean = 0.0, volume_sd = 0.0;   ///< wear volume / L³
  double largest_mean = 0.0;                   ///< mean over seeds of the largest particle diameter / L
  double contact_fraction = 0.0;               ///< mean A/A0
  bool valid = true;
};

/// One detached particle of one seed at one pixel.
struct MapParticle {
  std::uint64_t seed = 0;
  std::size_t load_index = 0, dstar_index = 0;
  double x = 0.0, y = 0.0, diameter = 0.0;  ///< / L
};

struct RoughWearMap {
  RoughWearMapSpec spec;
  std::vector<WearMapPixel> pixels;     ///< load-major: pixel(i_load, i_dstar) = pixels[i_load · n_dstar + i_dstar]
  std::vector<MapParticle> particles;
  double contact_seconds = 0.0;         ///< BEM solves
  double setup_seconds = 0.0;           ///< crack stresses, candidates and u of the full loading
  double detach_seconds = 0.0;          ///< the detachment procedure over every pixel and seed
  std::size_t candidates = 0;           ///< Σ over (seed, p̃_N) of the candidate particles
  std::size_t energy_evaluations = 0, solves = 0;
  const WearMapPixel& pixel(std::size_t i_load, std::size_t i_dstar) const {
    return pixels[i_load * spec.critical_diameters.size() + i_dstar];
  }
};

/// One surface's part of the map: what every pixel found on the surface of
/// seed `seeds[index]`.
struct SurfaceWearMap {
  std::size_t index = 0;                      ///< into spec.seeds
  std::vector<double> count, volume, largest;  ///< per (p̃_N, d*/L), load-major
  std::vector<double> contact_fraction;       ///< A/A0 per p̃_N
  std::vector<MapParticle> particles;
  double contact_seconds = 0.0, setup_seconds = 0.0, detach_seconds = 0.0;
  std::size_t candidates = 0, energy_evaluations = 0, solves = 0;
};

/// The surface of seed spec.seeds[index] over every pixel; progress(done,
/// total) after each p̃_N. NumericalError from the BEM.
SurfaceWearMap rough_wear_map_surface(const RoughWearMapSpec& spec, std::size_t index,
                                      const std::function<void(std::size_t, std::size_t)>& progress = {});

/// The map from its surfaces, one per seed in spec.seeds order: mean and
/// sample standard deviation per pixel, the invalid pixels flagged.
RoughWearMap combine_surfaces(const RoughWearMapSpec& spec, const std::vector<SurfaceWearMap>& surfaces);

/// Every surface in turn, then combined; progress(done, total) after each
/// (seed, p̃_N). NumericalError from the BEM.
RoughWearMap rough_wear_map(const RoughWearMapSpec& spec,
                            const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace wearscale::wear
