#pragma once
// The sliding cell of the wear studies of §7.2-7.3: a quasi-2D periodic box
// (x: sliding, y: thin periodic depth, z: normal) holding two first bodies
// and what lies between them, the bottom wall fixed, the top wall pressed at
// p_N and dragged at v. The bodies are carved from one relaxed amorphous box
// (§6.2.2). While sliding it samples the wall forces (averaged over each
// record interval, both walls), the worn particles (§7.2: more than half of
// the initial bonded neighbours lost) and the roughness Sa of both surfaces.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "wearscale/dem/amorphous_sample.hpp"
#include "wearscale/dem/cohesive_material.hpp"
#include "wearscale/dem/run_checkpoints.hpp"
#include "wearscale/dem/engine.hpp"
#include "wearscale/dem/simulation.hpp"
#include "wearscale/dem/worn_particles.hpp"

namespace wearscale::dem {

/// Body tags of the cell: the two first bodies and the third body between them.
inline constexpr int cell_bottom = 0, cell_top = 1, cell_third = 2;

struct SlidingCellSpec {
  CohesiveMaterial material;
  /// The contact law between the particles (contact_law.hpp; the cell's
  /// sample is relaxed, and worn particles are told, with the cohesive law's
  /// bonds either way) and its Coulomb μ where it has one.
  std::string law = "cohesive";
  double friction = 0.5;
  /// Tangential histories carried over neighbour rebuilds for touching pairs
  /// only, as LAMMPS did in the thesis' runs (NeighborSettings); by default
  /// every pair within reach keeps its history, as (6.4) defines it.
  bool history_of_touching_pairs_only = false;
  /// The engine that integrates the cell (engine.hpp: "wearscale", "lammps").
  std::string engine = "wearscale";
  double d0 = 0.0;                ///< mode of the particle diameters
  double largest = 0.0;           ///< d_l (0: 1.25 d0; §6.2.3 fixes it across discretizations)
  Vec3 box{};                     ///< L (sliding, periodic) × W (periodic depth) × H (normal)
  double wall_thickness = 1.5;    ///< in d0 (§6.3)
  double velocity = 10.0;         ///< sliding velocity of the top wall [m/s]
  double pressure = 0.5e9;        ///< p_N on the top wall [Pa] (§7.2, §7.3: 0.1 to 1 GPa)
  double time_step = 0.1;         ///< in Δt_c
  /// Viscous damping of the pressed wall's normal motion, as a fraction of
  /// the critical damping on the cell stiffness E A0 / H. Damping carries
  /// part of the load while the sample compacts, so keep it small.
  double wall_damping = 0.0;
  double sliding_distance = 0.0;  ///< [m]
  /// Loading at rest before sliding, for the time the wall takes to slide
  /// this far [m] (0: slide from the first step).
  double settle_distance = 0.0;
  long record_every = 200;        ///< steps per sample
  std::uint64_t seed = 1;
  double relax_tolerance = 1e-4;  ///< phase-2 stress tolerance of the relaxation, in E
  long max_relax_steps = 20000;
};

/// InputError naming the quantity, its value and the allowed range
/// (`study` prefixes the message).
void check(const SlidingCellSpec& spec, const char* study);

/// The relaxed amorphous box the bodies are carved from (d_s = 0.75 d0).
AmorphousSample make_cell_sample(const SlidingCellSpec& spec);

/// One sample of the history.
struct SlidingSample {
  double time = 0.0;
  double sliding = 0.0;           ///< top wall displacement along x
  double tangential_force = 0.0;  ///< resistance to sliding (> 0), mean of both walls over the interval
  double normal_force = 0.0;      ///< compressive force (> 0), mean of both walls over the interval
  double kinetic_energy = 0.0;
  double worn = 0.0;              ///< worn mobile particles (§7.2)
  double roughness_bottom = 0.0;  ///< Sa of the bottom surface (its unworn particles, facing up)
  double roughness_top = 0.0;     ///< Sa of the top surface (facing down)
};

class SlidingCell {
 public:
  /// Carved particles tagged with the body tags above, in their (relaxed)
  /// box; the walls are the particles within wall_thickness d0 of the lowest
  /// and highest centres. The bonded neighbours of every particle are
  /// recorded now, as the reference of the worn tagging.
  SlidingCell(Particles particles, Box box, const SlidingCellSpec& spec);
  SlidingCell(const SlidingCell&) = delete;
  SlidingCell& operator=(const SlidingCell&) = delete;

  /// Runs `steps` steps and samples the state.
  SlidingSample advance(long steps);
  /// The whole run: loading at rest (settle_steps()), then sliding, sampled
  /// every record_every steps (and at the end of the loading); `each` is
  /// called with every sample, the steps done and the steps planned. A run
  /// resumed from a checkpoint continues after step `from` (its state restored).
  void run(const std::function<void(const SlidingSample&, long step, long planned)>& each, long from = 0);
  long settle_steps() const { return settle_; }
  /// Loading and sliding steps.
  long planned_steps() const { return settle_ + slide_; }

  Engine& engine() { return *engine_; }
  const Engine& engine() const { return *engine_; }
  /// The worn flag of each particle now (walls never worn), as 0/1.
  std::vector<double> worn_flags() const;
  const WornParticles& tags() const { return *tags_; }
  const BondCriterion& bond() const { return bond_; }
  double area() const { return area_; }  ///< A0 = L W
  double time_step() const { return engine_->time_step(); }
  int top_wall() const { return top_wall_; }

 private:
  SlidingCellSpec spec_;
  std::unique_ptr<Engine> engine_;
  std::unique_ptr<WornParticles> tags_;
  BondCriterion bond_;
  int bottom_wall_ = 0, top_wall_ = 1;
  double area_ = 0.0;
  long settle_ = 0, slide_ = 0;
};

}  // namespace wearscale::dem
