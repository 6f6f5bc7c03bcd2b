#pragma once
// The sheared rough surfaces of thesis §7.2 (Figs. 7.4-7.7): two SiO2
// surfaces of self-affine roughness Sa (a fraction of the cell length L),
// carved from one relaxed amorphous box and put in contact at their highest
// summit, the bottom wall fixed, the top wall pressed at p_N and dragged at
// v. Particles that lose more than half of their initial bonded neighbours
// are worn. With d0 < d* the worn particles gather into rolling wear
// particles (low tangential force); with d0 ≫ d* a shear band grows (high
// tangential force). Sa of both surfaces is measured as they wear.
#include <functional>
#include <string>
#include <vector>

#include "wearscale/dem/sliding_cell.hpp"

namespace wearscale::dem {

struct RoughShearSpec {
  SlidingCellSpec cell;             ///< L × W × H, d0, p_N, v, slide
  double roughness = 0.02;          ///< initial Sa / L of each surface (thesis: 0.01, 0.02, 0.04)
  double hurst = 0.8;               ///< Hurst exponent of the profiles
  double shortest_wavelength = 4.0; ///< in d0: the profiles' shortest mode
};

struct RoughShearResult {
  std::size_t particles = 0;
  double d_star = 0.0;                       ///< 32γG/σ_m,T² (6.65)
  double time_step = 0.0;
  long steps = 0;
  long relaxation_steps = 0;
  double area = 0.0;                         ///< A0 = L W
  double imposed_roughness = 0.0;            ///< Sa of the carved profiles [m]
  std::vector<SlidingSample> history;        ///< the first row is the state before sliding
  double mean_pressure = 0.0;                ///< mean measured p_N over the second half of the slide
  double mean_tangential_force = 0.0;        ///< mean F_T over the second half
  double peak_tangential_force = 0.0;
  double friction = 0.0;                     ///< mean F_T / mean F_N over the second half
  std::size_t worn = 0;                      ///< worn particles at the end
  double worn_fraction = 0.0;                ///< of the mobile particles
  /// The largest cluster of worn particles (bonds between worn particles
  /// only; worn particles bonded to an unworn one, the lining of the
  /// surfaces, left out) at the start of the last fifth of the slide, and the
  /// Kabsch misfit of its motion over that window (0: rigid; rigid_fit.hpp).
  std::size_t wear_particle = 0;
  double wear_particle_residual = 0.0;
  /// "rolling wear particles": that cluster moved as a rigid body (misfit
  /// < 1/3); "shear band": it deformed (or no such cluster of 5 particles
  /// formed among many worn ones); "no wear particle": fewer than 5 worn.
  std::string regime;
};

/// Called after each sample with the cell (dumps, progress).
using RoughShearObserver = std::function<void(const SlidingCell&, const SlidingSample&, long step, long planned)>;

/// Builds the relaxed amorphous box (make_cell_sample) and runs the study.
RoughShearResult run_rough_shear(const RoughShearSpec& spec, const RoughShearObserver& observe = {},
                                 const RunCheckpoints& checkpoints = {});
/// The study on a given relaxed box (the same box for several runs).
RoughShearResult run_rough_shear(const RoughShearSpec& spec, const AmorphousSample& sample,
                                 const RoughShearObserver& observe = {}, const RunCheckpoints& checkpoints = {});

}  // namespace wearscale::dem
