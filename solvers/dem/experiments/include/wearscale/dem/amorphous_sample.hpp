#pragma once
// The amorphous sample of §6.2.2: log-normal diameters, random insertion into
// a periodic box up to a volume fraction, then a two-phase damped relaxation
// (repulsion only in a fixed box; then cohesion, no tangential force, in a
// box that moves until the internal stress vanishes), and finally masses
// adjusted so that the sample has the target density.
#include <cstdint>

#include "wearscale/dem/simulation.hpp"
#include "wearscale/dem/size_distribution.hpp"

namespace wearscale::dem {

struct AmorphousSpec {
  SizeDistribution sizes;         ///< d0, d_s, d_l
  Vec3 box_size{};                ///< the periodic box [0, L) before relaxation
  double volume_fraction = 0.75;  ///< Σ 4πr³/3 / V at insertion (§6.2.2)
  std::uint64_t seed = 1;
  int material = 0;               ///< material tag of every particle
  int body = 0;
  /// Number the inserted particles along the cells before relaxing them
  /// (cell_order.hpp): the relaxation runs 2-3 times faster at 10⁵ particles;
  /// a different (equally random) sample from the same seed. Otherwise the
  /// sample is relaxed in the order of insertion and numbered along the cells
  /// after it (the same sample, its pairs close in index for the runs that
  /// follow).
  bool numbered_along_cells = false;
};

struct RelaxationSettings {
  double time_step = 0.1;           ///< Δt / Δt_c (6.6)
  long repulsion_steps = 3000;      ///< phase 1, fixed box
  double repulsion_damping = 1.0;   ///< phase 1 global damping c / c_c (6.64)
  double cohesion_damping = 0.02;   ///< phase 2 global damping c / c_c
  double stress_tolerance = 1e-14;  ///< phase 2 ends when every |σ_aa| < tol E
  long max_cohesion_steps = 200000; ///< phase 2 gives up after this many steps
  /// Box rescaling per step in phase 2: along each periodic axis a, the box
  /// and positions are strained by ε_a = −rate σ_aa / E (a Berendsen
  /// barostat towards zero stress; tension shrinks the box).
  double barostat_rate = 0.02;
  double max_strain_per_step = 1e-3;  ///< cap on |ε_a| per step
  double skin = 0.2;                  ///< neighbour skin / d0
};

/// Σ 4πr³/3 over the particles, divided by the box volume (overlaps ignored).
double volume_fraction(const Particles& p, const Box& box);

/// The periodic box [0, size) and particles of diameters drawn from
/// spec.sizes at uniformly random positions in it, added until the volume
/// fraction is the closest to spec.volume_fraction (they overlap freely),
/// with the given density.
Particles insert_randomly(const AmorphousSpec& spec, double density);
Box periodic_box(const Vec3& size);

struct RelaxationReport {
  long repulsion_steps = 0;
  long cohesion_steps = 0;
  bool converged = false;  ///< phase 2 reached the stress tolerance
  SymTensor stress{};      ///< final box stress (shear included: the box keeps its shape)
  double modulus = 0.0;    ///< E of the tolerance (largest of the law's materials)
};

/// Relaxes a sample in place (§6.2.2). The simulation must use a
/// CohesiveLaw; the box is rescaled along its periodic axes only. "Internal
/// stress" is the box stress (virial_stress.hpp); the orthogonal box relaxes
/// its normal components, shear stress stays (typically 10⁻³ E) and is
/// reported. Afterwards the law's switches are restored, the time step and
/// damping are those of phase 2, and the virial is tracked.
RelaxationReport relax_amorphous(Simulation& sim, const RelaxationSettings& settings = {});

/// Rescales every mass (and moment of inertia) by one factor so that
/// Σ m / V_box = density.
void match_density(Particles& p, const Box& box, double density);

struct AmorphousSample {
  Particles particles;  ///< at rest, masses matching the target density
  Box box;
  double inserted_volume_fraction = 0.0;
  double relaxed_volume_fraction = 0.0;
  RelaxationReport relaxation;
};

/// The whole procedure for one material: insertion, relaxation, density.
AmorphousSample make_amorphous_sample(const CohesiveMaterial& material, const AmorphousSpec& spec,
                                      const RelaxationSettings& settings = {});

/// The relaxed box the carved studies start from (§6.3, §7.2, §7.3): sizes
/// from d_s = 0.75 d0 to d_l (0: 1.25 d0) about the mode d0, phase 2 of the
/// relaxation ending at `stress_tolerance` (in E) or after `max_cohesion_steps`;
/// `numbered_along_cells` as in AmorphousSpec.
AmorphousSample make_carving_sample(const CohesiveMaterial& material, double d0, double largest, const Vec3& box_size,
                                    std::uint64_t seed, double stress_tolerance, long max_cohesion_steps,
                                    bool numbered_along_cells = false);

}  // namespace wearscale::dem
