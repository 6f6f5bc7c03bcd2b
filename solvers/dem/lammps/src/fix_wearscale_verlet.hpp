#pragma once
// fix wearscale/verlet: wearscale's time integration inside LAMMPS, so that
// the LAMMPS engine moves particles as Simulation does: velocity Verlet with
// rotations (6.1) on the mobile particles, rigid walls of frozen particles
// (fixed, moving at a velocity, or pressed along an axis and integrated from
// the net force on them, with its damping), global viscous damping −c v, the
// net force on each wall at every step (summed over the ranks in rank order)
// and the checks that end a run: a non-finite velocity, or a particle moving
// further than the neighbour skin in one step. A wall is an atom group,
// excluded from the neighbour lists against itself.
//
// A run continues from the forces of the last step before it, as
// wearscale's own does between calls: LAMMPS starts each run by computing
// them again, at the full-step velocities where the step had the half-step
// ones (their damping and tangential parts differ), so this fix keeps each
// atom's force and torque at the end of a run (with the atom, through
// exchanges and restart files) and puts them back at the next run's start.
// compute_forces() (a run of 0 steps) computes them afresh, as Simulation's.
//
//   fix ID all wearscale/verlet SKIN
//
// The engine adds the walls and reads the state through the class.
#include <array>
#include <functional>
#include <vector>

#include "fix.h"
#include "wearscale/dem/vec3.hpp"
#include "wearscale/dem/wall.hpp"

namespace wearscale::dem::lammps {

/// One wall: its atom group, motion law and state (the same on every rank).
struct WallSlot {
  int groupbit = 0;
  WallMotion motion;
  double mass = 0.0;
  Vec3 velocity{}, force{}, displacement{};
};

/// Why a run stopped early: which particle (tag), and the value.
struct RunFailure {
  enum Kind { none = 0, skin = 1, non_finite = 2 };
  int kind = none;
  long long tag = 0;
  double value = 0.0;
  long long step = 0;  ///< the fix's step count when it was seen
};

class FixWearscaleVerlet : public LAMMPS_NS::Fix {
 public:
  FixWearscaleVerlet(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);
  ~FixWearscaleVerlet() override;
  int setmask() override;
  void init() override;
  void setup(int vflag) override;
  void initial_integrate(int vflag) override;
  void post_integrate() override;
  void post_force(int vflag) override;
  void final_integrate() override;
  void end_of_step() override;
  void post_run() override;

  void grow_arrays(int nmax) override;
  void copy_arrays(int i, int j, int delflag) override;
  int pack_exchange(int i, double* buf) override;
  int unpack_exchange(int nlocal, double* buf) override;
  int pack_restart(int i, double* buf) override;
  void unpack_restart(int nlocal, int nth) override;
  int size_restart(int) override { return 8; }
  int maxsize_restart() override { return 8; }

  std::vector<WallSlot> walls;
  double damping = 0.0;             ///< global damping c [force/velocity]
  long steps = 0;                   ///< steps taken since the system was made
  double time = 0.0;                ///< their summed time steps
  /// Called after every step (set on the rank that drives the engine).
  std::function<void()> each_step;
  /// Whether the next run starts from the forces kept at the end of the last
  /// one (a run), or computes them (compute_forces()).
  bool continue_forces = true;

  /// Collective: what stopped the run (kind none: nothing), the same on every rank.
  RunFailure agree_on_failure();

 private:
  int wall_of(int mask) const;
  double acceleration(const WallSlot& w) const;
  void sum_wall_forces();
  void fail(int kind, long long tag, double value);

  double skin_ = 0.0;
  std::vector<std::array<double, 7>> kept_;  // force, torque, and whether kept, per atom
  RunFailure failure_;        // this rank's first, since the last agreement
  std::vector<double> sums_;  // per-rank wall force sums, gathered
};

}  // namespace wearscale::dem::lammps
