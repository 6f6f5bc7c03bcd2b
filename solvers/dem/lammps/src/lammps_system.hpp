#pragma once
// One DEM system in a LAMMPS instance over an MPI communicator: the part of
// the LAMMPS engine every rank of the communicator runs alike (each call is
// collective). It makes the instance with wearscale's styles entered into
// LAMMPS' maps (Debian's LAMMPS has no PLUGIN package), creates the atoms
// wearscale built, and runs, gathers, writes and reads restarts. What is
// not LAMMPS' (the mirror of the particles the drivers read, the protocol
// between ranks) is lammps_engine.cpp's.
#include <mpi.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "fix_wearscale_verlet.hpp"
#include "wearscale/dem/box.hpp"
#include "wearscale/dem/cohesive_material.hpp"
#include "wearscale/dem/neighbor_list.hpp"
#include "wearscale/dem/pair_loop.hpp"
#include "wearscale/dem/particles.hpp"
#include "wearscale/dem/wall.hpp"

namespace LAMMPS_NS {
class LAMMPS;
}

namespace wearscale::dem::lammps {

class PairWearscale;

/// The contact law as the pair style takes it.
struct LawConfig {
  enum class Kind { Cohesive, Hooke };
  Kind kind = Kind::Cohesive;
  /// Cohesive: the targets of each pair of materials (types² of them, row-major).
  std::vector<CohesiveMaterial> materials;
  int types = 1;
  bool cohesion = true, tangential = true;
  /// Hooke: k_N, k_T, γ_N, γ_T, μ.
  double k_n = 0.0, k_t = 0.0, gamma_n = 0.0, gamma_t = 0.0, friction = 0.0;
};

/// Everything the commands of a system are made from (the same on every rank).
struct SystemConfig {
  Box box;
  LawConfig law;
  NeighborSettings neighbors;
  double time_step = 0.0;
  double damping = 0.0;
  bool track_virial = false;
};

/// The particles a system starts from (on every rank).
struct AtomTable {
  std::size_t count = 0;
  std::vector<double> x, v, omega;  // 3 a particle
  std::vector<double> radius, mass;
  std::vector<int> type;            // material + 1
  std::vector<int> image;           // 3 a particle
};

/// The dynamic state of every particle, on the root rank after gather().
struct GatheredState {
  std::vector<double> x, v, omega, force, torque, virial;  // 3 (virial: 6) a particle, by index = tag − 1
  std::vector<std::int32_t> image;                          // 3 a particle
};

class LammpsSystem {
 public:
  /// Creates the instance over `comm` and the atoms of `atoms` (tag = index + 1).
  LammpsSystem(MPI_Comm comm, SystemConfig config, const AtomTable& atoms);
  ~LammpsSystem();
  LammpsSystem(const LammpsSystem&) = delete;
  LammpsSystem& operator=(const LammpsSystem&) = delete;

  /// Wall `slot.motion` of the particles whose index is in `members`.
  void add_wall(const std::vector<std::size_t>& members, WallSlot slot);
  void set_time_step(double dt);
  void set_damping(double c);
  void set_track_virial(bool on);
  void set_wall_velocity(int wall, int axis, double velocity);
  /// `steps` steps (one LAMMPS run); `each_step` after each (this rank's).
  /// Returns what stopped it early, agreed by every rank (kind none: nothing).
  RunFailure run(long steps, const std::function<void()>& each_step);
  /// Forces at the current positions (a LAMMPS run of 0 steps).
  void compute_forces();
  /// Every particle's state onto `root` (into `out` there).
  void gather(int root, GatheredState& out) const;
  /// A restart file of the state, its bytes on `root`; read back on every
  /// rank by restore() (a fresh instance with this system's settings).
  std::string write_restart(int root) const;
  void restore(int root, const std::string& bytes);

  const std::vector<WallSlot>& walls() const;
  long steps() const;
  double time() const;
  /// Overwrites the integrator's clock and walls (a restored state's).
  void set_clock(long steps, double time, const std::vector<WallSlot>& walls);
  const SystemConfig& config() const { return config_; }
  /// LAMMPS' own version date (e.g. 20210929).
  int lammps_version() const;

 private:
  void open();
  void command(const std::string& line);
  /// The commands after the atoms exist (styles, neighbours, the fix, walls' groups).
  void configure(bool fresh);
  void apply_wall_groups();
  /// After read_restart: the shrink-wrap margins of the created box.
  void keep_created_margins();
  std::string temporary_file(int root) const;

  MPI_Comm comm_;
  int rank_ = 0;
  SystemConfig config_;
  std::size_t count_ = 0;
  std::vector<std::int16_t> wall_of_;  // per particle: its wall or −1 (every rank)
  std::vector<WallSlot> walls_;        // the walls as added (the fix holds their state)
  // The box LAMMPS was created with: its shrink-wrapped bounds keep a margin
  // of 1e-4 of these lengths, which restore() gives back (not the saved box's).
  Vec3 created_lo_{}, created_hi_{};
  LAMMPS_NS::LAMMPS* lmp_ = nullptr;
  FixWearscaleVerlet* verlet_ = nullptr;
  PairWearscale* pair_ = nullptr;
};

/// Enters wearscale's styles into an instance's maps.
void register_styles(LAMMPS_NS::LAMMPS* lmp);
/// The version of the LAMMPS library, e.g. "29 Sep 2021" (MPI initialised).
std::string library_version();

}  // namespace wearscale::dem::lammps
