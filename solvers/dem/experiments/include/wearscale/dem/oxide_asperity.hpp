#pragma once
// The oxidized-asperity study of thesis §9.3.3 (Fig. 9.26): a crystalline Si
// substrate (HCP lattice, close-packed planes parallel to the surface) under
// an amorphous SiO2 layer, a loose amorphous SiO2 cylinder (axis along y)
// lying on the layer, and a rigid SiO2 plate above it, pressed at p_N and
// dragged along x. Periodic in x and y; the lowest Si layers are a fixed
// wall. The thesis shows the cylinder rolling, growing by taking particles
// from the layer, and reaching the Si, leaving a trench.
//
// While sliding it measures the wall forces (as the sliding cell), and at
// every `track_distance` of slide the rolling body: its members are the
// connected component (cohesive bonds, clusters.hpp) of mobile particles that
// moved with the body's rigid motion (Kabsch, rigid_fit.hpp) over the window;
// the body's rotation about y and its travel are summed over the windows. The
// trench: the height of the layer surface (the tops of the Si and layer
// particles not in the body, averaged over y in bins of d0 along x) over the
// strip the body has passed, against its height before sliding.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "wearscale/dem/cohesive_material.hpp"
#include "wearscale/dem/run_checkpoints.hpp"
#include "wearscale/dem/vec3.hpp"

namespace wearscale::dem {

class Engine;

/// Body tags: the Si substrate, the SiO2 layer, the loose cylinder, the plate.
inline constexpr int asperity_substrate = 0, asperity_layer = 1, asperity_body = 2, asperity_plate = 3;

struct OxideAsperitySpec {
  CohesiveMaterial oxide;      ///< SiO2: layer, cylinder, plate (material tag 0)
  CohesiveMaterial substrate;  ///< Si: the HCP substrate (material tag 1)
  /// The targets of SiO2–Si pairs; empty: mix(oxide, substrate).
  std::optional<CohesiveMaterial> interface;
  double d0 = 1.5e-9;          ///< HCP spacing of the Si, mode of the SiO2 diameters
  double largest = 0.0;        ///< d_l of the SiO2 (0: 1.25 d0)
  /// x, y (periodic) and z: x is rounded to whole HCP cells of d0 and y of
  /// √3 d0, so that the Si lattice is periodic.
  Vec3 box{150e-9, 150e-9, 75e-9};
  double layer_thickness = 5e-9;  ///< the SiO2 layer on the Si
  double body_diameter = 50e-9;   ///< the loose cylinder
  double clearance = 0.25;        ///< gaps layer–cylinder and cylinder–plate, in d0
  double plate_thickness = 1.5;   ///< the rigid plate, in d0
  double wall_thickness = 1.5;    ///< the fixed bottom Si wall, in d0
  double velocity = 10.0;         ///< plate sliding velocity [m/s]
  double pressure = 100e6;        ///< p_N on the plate [Pa]
  double time_step = 0.1;         ///< in Δt_c (6.6)
  double sliding_distance = 150e-9;
  /// Loading at rest before sliding, for the time the plate takes to slide
  /// this far; the mobile particles are damped (settle_damping c_c, (6.64))
  /// meanwhile, so that the layer set on the lattice comes to rest bonded.
  double settle_distance = 3e-9;
  double settle_damping = 0.1;
  double track_distance = 0.0;    ///< slide between body updates (0: 2 d0)
  long record_every = 200;        ///< steps per sample of the history
  std::uint64_t seed = 1;
  double relax_tolerance = 1e-4;  ///< of the amorphous SiO2 (§6.2.2), in E
  long max_relax_steps = 20000;
  /// Particles renumbered along the cells every this many neighbour builds
  /// (NeighborSettings::renumber_every; 0: never).
  int renumber_every = 0;
  /// The engine that integrates the run (engine.hpp: "wearscale", "lammps").
  std::string engine = "wearscale";
};

/// InputError naming the quantity, its value and the allowed range.
void check(const OxideAsperitySpec& spec);

/// One sample of the history.
struct OxideAsperitySample {
  double time = 0.0;
  double sliding = 0.0;           ///< plate displacement along x
  double tangential_force = 0.0;  ///< resistance to sliding (> 0), mean of both walls over the interval
  double normal_force = 0.0;      ///< compressive force (> 0), mean of both walls over the interval
  double kinetic_energy = 0.0;
  double body_particles = 0.0;    ///< particles of the rolling body
  double picked_up = 0.0;         ///< of those, taken from the layer or the substrate
  double rotation = 0.0;          ///< body rotation about y since sliding started [rad] (> 0: rolling with the plate)
  double travel = 0.0;            ///< body centre displacement along x since sliding started
  double trench_depth = 0.0;      ///< initial surface height − mean height over the strip passed (0: none yet)
  double trench_max_depth = 0.0;  ///< initial surface height − lowest bin of that strip
};

struct OxideAsperityResult {
  std::size_t particles = 0, substrate_particles = 0, layer_particles = 0, body_particles = 0, plate_particles = 0;
  Vec3 box{};                      ///< as built (whole HCP cells)
  double time_step = 0.0;
  long steps = 0;                  ///< settle + slide
  long relaxation_steps = 0;
  /// The relaxed SiO2 block is scaled by relax_scale (positions and radii)
  /// to the lattice's periodic lengths, and strained in plane by at most
  /// relax_strain beyond that (the two lengths did not relax alike).
  double relax_scale = 1.0, relax_strain = 0.0;
  double substrate_top = 0.0;      ///< Si surface: highest site + d0/2
  double surface_height = 0.0;     ///< layer surface height before sliding
  double layer_measured = 0.0;     ///< surface_height − substrate_top
  std::vector<OxideAsperitySample> history;  ///< the first row is the state before loading
  double mean_tangential_force = 0.0, mean_normal_force = 0.0;  ///< over the second half of the slide
  double friction = 0.0;           ///< their ratio
  double final_body = 0.0, final_picked_up = 0.0;
  double rotation = 0.0, travel = 0.0;
  /// |rotation| × initial radius / travel: 1 for rolling without slip on the
  /// layer, 0 for a body sliding without turning.
  double rolling_ratio = 0.0;
  double trench_depth = 0.0, trench_max_depth = 0.0;
  /// Slide at which the deepest bin of the trench first came within d0/4 of
  /// the Si surface (negative: not reached).
  double reached_substrate_at = -1.0;
};

/// Called after each sample: the system, the sample, the steps done and
/// planned, and the body flag of each particle (1: in the rolling body).
using OxideAsperityObserver =
    std::function<void(const Engine&, const OxideAsperitySample&, long step, long planned, const std::vector<double>& body)>;

/// Offers its state after every sample (run_checkpoints.hpp): a run started
/// `from` one sets the system up as before, restores it and ends bit for bit
/// as the run that never stopped.
OxideAsperityResult run_oxide_asperity(const OxideAsperitySpec& spec, const OxideAsperityObserver& observe = {},
                                       const RunCheckpoints& checkpoints = {});

}  // namespace wearscale::dem
