#pragma once
// A DEM system and its time integration: particles in a box, a force law,
// walls, a neighbour list, and velocity Verlet with rotations (6.1).
//
// With NeighborSettings::renumber_every the system renumbers its particles
// in cell order at neighbour builds, inside its calls: outside them (and
// through particles() and virial() anywhere) the particles are in the order
// they were handed in, the walls' members are those indices, and every
// index a user holds keeps its particle. Inside an observer of run(),
// particles() restores that order (a pass over the particles; the walls and
// the clock need none), so a reference to the particles taken before run()
// is read there only after a call of particles().
#include <array>
#include <concepts>
#include <cstddef>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "wearscale/core/checkpoint_state.hpp"
#include "wearscale/dem/box.hpp"
#include "wearscale/dem/cohesive_law.hpp"
#include "wearscale/dem/contact_law.hpp"
#include "wearscale/dem/hooke_law.hpp"
#include "wearscale/dem/neighbor_list.hpp"
#include "wearscale/dem/pair_loop.hpp"
#include "wearscale/dem/particles.hpp"
#include "wearscale/dem/wall.hpp"

namespace wearscale::dem {

class Simulation {
 public:
  Simulation(Particles particles, Box box, std::unique_ptr<ContactLaw> law, NeighborSettings neighbors);
  template <std::derived_from<ContactLaw> Law>
  Simulation(Particles particles, Box box, Law law, NeighborSettings neighbors)
      : Simulation(std::move(particles), box, std::make_unique<Law>(std::move(law)), neighbors) {}
  Simulation(Simulation&&) noexcept = default;
  Simulation& operator=(Simulation&&) noexcept = default;

  Particles& particles() {
    in_user_order();
    return particles_;
  }
  const Particles& particles() const {
    in_user_order();
    return particles_;
  }
  Box& box() { return box_; }
  const Box& box() const { return box_; }
  /// The contact law. Changing its parameters is allowed between steps
  /// (call reset() when that changes its reach or per-pair parameters).
  ContactLaw& law() { return *law_; }
  const ContactLaw& law() const { return *law_; }
  /// The law as its class; InputError naming both when it is another one.
  template <std::derived_from<ContactLaw> Law>
  Law& law_as() {
    return const_cast<Law&>(std::as_const(*this).law_as<Law>());
  }
  template <std::derived_from<ContactLaw> Law>
  const Law& law_as() const {
    if (const auto* l = dynamic_cast<const Law*>(law_.get())) return *l;
    throw_wrong_law();
  }
  const NeighborList& neighbor_list() const { return neighbors_; }

  /// Freezes `members` into a rigid wall; returns its index.
  int add_wall(std::vector<std::size_t> members, WallMotion motion);
  Wall& wall(int w) { return walls_[static_cast<std::size_t>(w)]; }
  const Wall& wall(int w) const { return walls_[static_cast<std::size_t>(w)]; }
  std::size_t wall_count() const { return walls_.size(); }

  void set_time_step(double dt);
  double time_step() const { return dt_; }
  /// Global viscous damping force −c v on every mobile particle.
  void set_global_damping(double c) { global_damping_ = c; }
  double global_damping() const { return global_damping_; }
  /// Keeps a per-particle virial (for stresses) up to date at each step.
  void set_track_virial(bool on) { track_virial_ = on; }

  /// The particle set, radii, masses or law changed: rebuild from scratch
  /// (tangential histories are dropped when particles were removed).
  void reset();

  /// One velocity-Verlet step (6.1). Throws NumericalError when a velocity
  /// becomes non-finite or a particle jumps further than the skin in a step.
  void step();
  /// Where run() may stop on SIGINT/SIGTERM besides the start of the call.
  enum class StopInside {
    Yes,  ///< also every 1024 steps, and at the next step once the call has run 5 s
    No,   ///< never: a driver that runs in chunks and checkpoints between them
          ///< (its checkpoint, saved after the chunk, then holds the stop's state)
  };
  /// `steps` steps; `observe(step)` after each when given. Throws
  /// Interrupted when SIGINT/SIGTERM arrived (see StopInside).
  void run(long steps, const std::function<void(long)>& observe = {}, StopInside inside = StopInside::Yes);

  long step_count() const { return step_; }
  double time() const { return time_; }

  /// Forces and torques at the current positions (also updates the virial);
  /// tangential histories are not advanced (as in LAMMPS' setup).
  void compute_forces();

  /// The dynamic state for a checkpoint, bit for bit: every particle array,
  /// the box, the walls and their motion, the neighbour list with its
  /// tangential histories, the clock and the time step. The force law and
  /// the neighbour settings are the system's set-up, not state: a run is
  /// resumed by setting the system up as before, then restore_state().
  void save_state(CheckpointState& out) const;
  /// Continues from a saved state: the next step() is the one the saved run
  /// would have taken (same result bit for bit with the same thread count).
  /// InputError naming the entry if the checkpoint is not a DEM state.
  void restore_state(const CheckpointState& in);

  /// Per-particle virial W_i = ½ Σ_j r_ij ⊗ f_ij (only with set_track_virial).
  const std::vector<SymTensor>& virial() const {
    in_user_order();
    return virial_;
  }
  /// How many times the particles were renumbered (NeighborSettings::renumber_every).
  long renumberings() const { return renumberings_; }
  /// Blocks of rows of the threaded pair loop's two colours at the last
  /// build (pair_loop.hpp; 0: one thread, or per-thread buffers).
  std::size_t colour_blocks() const { return block_start_.empty() ? 0 : block_start_.size() - 1; }

  /// Translational + rotational kinetic energy of the mobile particles.
  double kinetic_energy() const;
  /// A stable time step for this system: 0.1 Δt_c (6.6) of its lightest
  /// mobile particle against its stiffest contact (what a blow-up suggests).
  double stable_time_step() const;
  /// Energy stored in the pair springs (normal + tangential).
  double potential_energy() const;
  /// Σ m v over all particles (walls included).
  Vec3 momentum() const;
  /// Interaction range beyond contact, max δ_f (0 for contact-only laws).
  double reach() const;

 private:
  [[noreturn]] void throw_wrong_law() const;
  /// advance: the step's force evaluation, which moves the sliding histories;
  /// cleared: the forces, torques and virials are already zero.
  void forces(bool advance, bool cleared = false);
  void prepare_pairs();
  /// The kicks of velocity Verlet (6.1) in one pass: `second`, the second
  /// half-kick of the step whose forces are in (the step then counts as
  /// done); `first`, the next step's first half-kick and drift, which with
  /// clear_forces zeroes the forces, torques and (tracked, sized) virials
  /// once read (its force evaluation then needs no pass of its own).
  void kick(bool second, bool first, bool clear_forces);
  bool clears_forces_in_kick() const;
  /// A step up to its first half-kick: the forces it starts from.
  void start_step();
  /// After the first half-kick: the list rebuilt if due, the step's forces.
  void finish_step_forces();
  void rebuild();
  /// The particles (and their pairs) renumbered in cell order.
  void renumber();
  /// The arrays in the system's own numbering (a no-op unless renumbered),
  /// or in the user's; walls' members in slots (wall_slots_) either way.
  void in_slot_order() const;
  void in_user_order() const;
  /// The arrays reordered: new[k] = old[from[k]].
  void gather(const std::vector<std::uint32_t>& from) const;
  const std::vector<std::size_t>& wall_slots(std::size_t w) const {
    return user_of_.empty() ? walls_[w].members : wall_slots_[w];
  }
  void map_walls();
  /// In the system's own numbering for the scope of a call, the user's after.
  class SlotOrder {
   public:
    explicit SlotOrder(const Simulation& s) : sim_(s) { sim_.in_slot_order(); }
    ~SlotOrder() { sim_.in_user_order(); }
    SlotOrder(const SlotOrder&) = delete;
    SlotOrder& operator=(const SlotOrder&) = delete;

   private:
    const Simulation& sim_;
  };

  // mutable: the order the arrays are held in is not the system's state
  // (in_user_order from the const accessors).
  mutable Particles particles_;
  Box box_;
  std::unique_ptr<ContactLaw> law_;
  NeighborSettings settings_;
  NeighborList neighbors_;
  std::vector<Wall> walls_;
  // Each wall's velocity after a kick and its displacement in the drift.
  struct WallMove {
    Vec3 velocity, dx;
  };
  std::vector<WallMove> wall_moves_;
  // Row blocks of the threaded pair loop's two colours (empty: buffers).
  std::vector<std::size_t> block_start_;
  // Per-thread force/torque/virial buffers (threads 1..T-1), only for lists
  // that reach too far in index for the colour blocks.
  std::vector<std::vector<Vec3>> thread_force_, thread_torque_;
  std::vector<std::vector<SymTensor>> thread_virial_;
  mutable std::vector<SymTensor> virial_;
  // Renumbering: slot k holds the user's particle user_of_[k], user's u sits
  // in slot slot_of_[u] (both empty: never renumbered); in_slots_, the
  // arrays are in slot order now. wall_slots_: the walls' members as slots.
  std::vector<std::uint32_t> user_of_, slot_of_;
  mutable bool in_slots_ = false;
  std::vector<std::vector<std::size_t>> wall_slots_;
  mutable std::vector<std::byte> reorder_scratch_;
  long renumberings_ = 0;
  std::array<Vec3, PeriodicImages::max_count> shift_table_{};  // offsets of the list's images
  double dt_ = 0.0;
  double global_damping_ = 0.0;
  bool track_virial_ = false;
  bool forces_valid_ = false;
  long step_ = 0;
  long since_build_ = 0;
  double time_ = 0.0;
};

}  // namespace wearscale::dem
