#pragma once
// The sheared junction of thesis §6.3: two amorphous surfaces linked by a
// cylindrical junction of diameter D and height D/2, the bottom wall fixed,
// the top wall dragged at a constant velocity under a normal pressure. A
// junction below the material's critical size d* deforms plastically; above
// it, it detaches (by fracture) into a rolling wear particle.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "wearscale/dem/cohesive_material.hpp"
#include "wearscale/dem/run_checkpoints.hpp"
#include "wearscale/dem/vec3.hpp"

namespace wearscale::dem {

class Engine;

struct ShearedJunctionSpec {
  CohesiveMaterial material;
  double diameter = 0.0;           ///< junction diameter D
  double d0 = 0.0;                 ///< mode of the particle diameters
  double largest = 0.0;            ///< d_l (0: 1.25 d0); §6.3 fixes d_l = 7.5 nm
  Vec3 box{60e-9, 40e-9, 40e-9};   ///< x: sliding (periodic), y: periodic, z: normal
  double height_ratio = 0.5;       ///< H = ratio · D
  double wall_thickness = 1.5;     ///< in d0
  double velocity = 10.0;          ///< top wall sliding velocity [m/s]
  double pressure = 100e6;         ///< normal pressure on the top wall [Pa]
  double time_step = 0.1;          ///< in Δt_c
  double sliding_distance = 0.0;   ///< 0: 1.5 D
  long record_every = 100;         ///< steps between samples of the force history
  unsigned seed = 1;
  /// Relaxation of the amorphous box before carving (§6.2.2); phase 2 stops at
  /// this stress (in E) or after max_relax_steps.
  double relax_tolerance = 1e-4;
  long max_relax_steps = 20000;
  /// The engine that integrates the run (engine.hpp: "wearscale", "lammps").
  std::string engine = "wearscale";
};

/// One sample of the history.
struct JunctionSample {
  double time = 0.0;
  double sliding = 0.0;           ///< top wall displacement along x
  double tangential_force = 0.0;  ///< resistance of the sample to sliding (> 0)
  double normal_force = 0.0;      ///< compressive force on the top wall (> 0)
  double kinetic_energy = 0.0;
};

struct ShearedJunctionResult {
  std::size_t particles = 0, junction_particles = 0;
  double d_star = 0.0;                 ///< 32γG/σ_m,T² (6.65)
  double time_step = 0.0;
  long steps = 0;
  long relaxation_steps = 0;
  std::vector<JunctionSample> history;
  double peak_tangential_force = 0.0;
  /// Cluster analysis of the original bonds still intact at the end: the
  /// junction particles in the largest cluster that touches no wall
  /// (diagnostic: a rolling particle can keep a few original bonds to a
  /// surface through particles it tore off, so the verdict uses the motion).
  std::size_t detached_cluster = 0;
  double detached_diameter = 0.0;      ///< that cluster's equivalent diameter
  /// Best rigid motion (Kabsch) of the junction's particles over the last
  /// fifth of the slide: RMS misfit over RMS displacement (small for a rigid
  /// rolling particle), and its rotation about y over slide/D (≈ 1 when
  /// rolling without slip between the surfaces).
  double rigid_residual = 0.0;
  double rolling_rate = 0.0;
  /// Detached into a rolling particle: rigid_residual < 1/3 and rolling_rate > ½.
  bool detached = false;
  std::string verdict() const { return detached ? "detached into a rolling particle" : "deformed plastically"; }
};

/// Called every record_every steps with the engine (dumps, progress).
using JunctionObserver = std::function<void(const Engine&, const JunctionSample&, long step, long planned)>;

/// `checkpoints` offers the state after every sample and resumes from one.
ShearedJunctionResult run_sheared_junction(const ShearedJunctionSpec& spec, const JunctionObserver& observe = {},
                                           const RunCheckpoints& checkpoints = {});

}  // namespace wearscale::dem
