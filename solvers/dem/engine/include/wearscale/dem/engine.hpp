#pragma once
// The engine that integrates a DEM system: what the experiment drivers (patch
// test, junctions, sliding cells, oxide asperity) ask of it. A driver builds
// its sample in wearscale (lattices, amorphous samples, carving, walls'
// members, tags) and hands the particles to an engine made by name:
// "wearscale" (Simulation, this library) or "lammps" (solvers/dem/lammps: the
// same laws as LAMMPS pair styles, over MPI ranks), registered by the library
// that provides it. Every engine runs velocity Verlet with rotations (6.1),
// the contact law, rigid walls (fixed, moving, pressed) and global damping with
// the same meaning; the state it reports (particles(), walls) is the one the
// drivers measure.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "wearscale/core/checkpoint_state.hpp"
#include "wearscale/dem/box.hpp"
#include "wearscale/dem/contact_law.hpp"
#include "wearscale/dem/neighbor_list.hpp"
#include "wearscale/dem/pair_loop.hpp"
#include "wearscale/dem/particles.hpp"
#include "wearscale/dem/wall.hpp"

namespace wearscale::dem {

/// What an engine is made from: the particles (ids, tags, masses as built),
/// their box, the contact law and the neighbour settings.
struct EngineSetup {
  Particles particles;
  Box box;
  std::unique_ptr<ContactLaw> law;
  NeighborSettings neighbors;
};

class Engine {
 public:
  virtual ~Engine() = default;
  /// The registered name ("wearscale", "lammps").
  virtual std::string_view name() const = 0;

  // --- Set-up (before the first step, or between runs) ----------------------
  /// Freezes `members` (particle indices) into a rigid wall; returns its index.
  virtual int add_wall(std::vector<std::size_t> members, WallMotion motion) = 0;
  virtual void set_time_step(double dt) = 0;
  /// Global viscous damping force −c v on every mobile particle.
  virtual void set_global_damping(double c) = 0;
  /// Keeps the per-particle virial (virial()) up to date at each step.
  virtual void set_track_virial(bool on) = 0;
  /// The velocity of wall w along `axis` (0, 1, 2): e.g. the start of sliding.
  virtual void set_wall_velocity(int w, int axis, double velocity) = 0;

  // --- Running ---------------------------------------------------------------
  /// Whether run() may stop on SIGINT/SIGTERM inside the call (Simulation::StopInside).
  enum class StopInside { Yes, No };
  /// `steps` steps of velocity Verlet (6.1). `each_step(step)`, when given,
  /// is called after every step and may read wall(): its forces and motion
  /// (the particles are brought up to date at the end of the call).
  /// NumericalError on a non-finite velocity or a particle that jumps more
  /// than the neighbour skin in one step; Interrupted on SIGINT/SIGTERM at
  /// the start of the call (and inside it with StopInside::Yes, where the
  /// engine can).
  virtual void run(long steps, const std::function<void(long)>& each_step = {},
                   StopInside inside = StopInside::No) = 0;
  /// Forces, torques and virials at the current positions (the histories do
  /// not move, as in LAMMPS' setup).
  virtual void compute_forces() = 0;

  // --- State, as of the end of the last call --------------------------------
  virtual const Particles& particles() const = 0;
  virtual const Box& box() const = 0;
  virtual const ContactLaw& law() const = 0;
  virtual const Wall& wall(int w) const = 0;
  virtual std::size_t wall_count() const = 0;
  virtual double time_step() const = 0;
  virtual long step_count() const = 0;
  virtual double time() const = 0;
  /// Per-particle virial W_i = ½ Σ_j (x_j − x_i) ⊗ f_ij (with set_track_virial).
  virtual const std::vector<SymTensor>& virial() const = 0;
  /// Translational + rotational kinetic energy of the mobile particles.
  virtual double kinetic_energy() const = 0;
  /// Whether tangential histories carry over neighbour rebuilds for touching
  /// pairs only (NeighborSettings::history_of_touching_pairs_only).
  virtual bool history_of_touching_pairs_only() const = 0;

  /// The dynamic state for a checkpoint (see Simulation::save_state): a run
  /// is resumed by setting the system up as before, then restore_state();
  /// it continues bit for bit with the same engine on the same ranks.
  virtual void save_state(CheckpointState& out) const = 0;
  virtual void restore_state(const CheckpointState& in) = 0;
};

/// Makes an engine from its set-up.
using EngineFactory = std::unique_ptr<Engine> (*)(EngineSetup setup);

/// Registers an engine under `name` (again: replaced). "wearscale" is always there.
void register_engine(const std::string& name, EngineFactory make);
/// The registered engines, in name order.
std::vector<std::string> engine_names();
/// The engines a case may name (registered or not in this build), for the key's doc.
inline constexpr std::string_view engine_choices = "wearscale | lammps";
/// InputError naming the registered engines when `name` is not one of them
/// (for "lammps" in a build without it: how to get it).
std::unique_ptr<Engine> make_engine(std::string_view name, EngineSetup setup);

/// Translational + rotational kinetic energy of the mobile particles of `p`.
double kinetic_energy(const Particles& p);

}  // namespace wearscale::dem
