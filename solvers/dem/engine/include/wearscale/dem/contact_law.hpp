#pragma once
// A DEM contact law: the sub-model that turns the state of one pair of
// spheres into the force and torque between them. Each law is one class in
// one file with its registration line (WEARSCALE_CONTACT_LAW) beside it; a
// case selects one by name (`[dem] law`).
//
// The pair loop is not a virtual call per pair: add_pair_forces() is called
// once per force evaluation and runs pair_loop.hpp's loop instantiated on
// the concrete law, whose pair force the compiler inlines.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "wearscale/dem/cohesive_material.hpp"
#include "wearscale/dem/vec3.hpp"

namespace wearscale::dem {

class Particles;
class NeighborList;
struct PairLoop;

/// What a law sees of one pair: i, its neighbour j (at the image in the
/// list) and their kinematics. The pair loop gathers these for a batch of
/// pairs and calls the law's
///   PairForce contact(k, state, const double* history, double* updated, dt, advance)
/// on each lane of a vectorised loop (history: the pair's doubles before the
/// step, updated: where to write them, every one of them). A contact() should
/// be straight-line arithmetic: every value computed, the one that applies
/// selected (`c ? a : b`), no early return — which is what lets the
/// compiler vectorise it, with the same bits as branching.
struct PairState {
  Vec3 d;  ///< x_j − x_i (the listed image of j)
  Vec3 v;  ///< v_i − v_j
  Vec3 w;  ///< r_i ω_i + r_j ω_j
  double ri, rj, mi, mj;
};

/// What a law returns for one pair: the force on i (j gets its opposite) and
/// its tangential part, which makes the torques r_i n × F_T and r_j n × F_T.
/// c ? a : b as a blend of bits, never as a branch: a select that feeds a
/// store stays a select (the compiler turns nested `?:` into branches around
/// the store, which stops the vectoriser). Exact: one of a, b, bit for bit.
inline double select(bool c, double a, double b) {
  const std::uint64_t mask = std::uint64_t{0} - static_cast<std::uint64_t>(c);
  return std::bit_cast<double>((std::bit_cast<std::uint64_t>(a) & mask) | (std::bit_cast<std::uint64_t>(b) & ~mask));
}

struct PairForce {
  Vec3 force;
  Vec3 tangential;
  Vec3 normal;  ///< unit vector from i to j
  bool active;  ///< false: the pair is out of range (no force, history cleared)
};

class ContactLaw {
 public:
  virtual ~ContactLaw() = default;
  virtual std::unique_ptr<ContactLaw> clone() const = 0;
  /// The registered name (`[dem] law`).
  virtual std::string_view name() const = 0;

  /// Doubles of history stored per pair (kept over rebuilds, wraps and
  /// checkpoints by the neighbour list).
  virtual int history_size() const { return 3; }
  /// The history of pair (j, i) from that of (i, j), in place (when the
  /// particles are renumbered and a pair changes sides). By default every
  /// double is negated: a relative displacement of i from j, as the
  /// tangential springs of both laws here (and LAMMPS' fix neigh/history).
  virtual void reverse_history(double* history) const {
    for (int c = 0; c < history_size(); ++c) history[c] = -history[c];
  }
  /// The longest separation beyond contact at which a pair still interacts,
  /// for particles of radius ≤ max_radius (0: contact only).
  virtual double pull_off_distance(double max_radius) const = 0;
  /// The critical time step Δt_c (6.6) of these particles under this law:
  /// the lightest against the stiffest contact.
  virtual double critical_time_step(const Particles& p) const = 0;

  /// Called after every neighbour-list build (per-pair parameters).
  virtual void prepare(const Particles& p, const NeighborList& list);
  /// Adds every listed pair's forces, torques (and virial) into `loop`.
  virtual void add_pair_forces(PairLoop& loop) const = 0;
  /// Adds the energy stored in pair k's springs at surface separation delta
  /// (positive apart) with its history to `energy`.
  virtual void add_pair_energy(const Particles& p, std::size_t i, std::size_t j, std::size_t k, double delta,
                             const double* history, double& energy) const = 0;
};

/// What a registered law may be built from: the material table (a
/// particle's material tag indexes it) and the case's typical diameter.
struct ContactLawInputs {
  std::vector<CohesiveMaterial> materials;
  double diameter = 0.0;
  double friction = 0.5;  ///< Coulomb μ, for laws with a friction coefficient
};

using ContactLawFactory = std::unique_ptr<ContactLaw> (*)(const ContactLawInputs&);

struct ContactLawEntry {
  const char* name;
  const char* doc;
  ContactLawFactory make;
};

/// The registered laws, in name order.
const std::vector<ContactLawEntry>& contact_laws();
std::vector<std::string> contact_law_names();
/// InputError naming the known laws when `name` is not one of them.
std::unique_ptr<ContactLaw> make_contact_law(std::string_view name, const ContactLawInputs& inputs);

}  // namespace wearscale::dem

/// The registration line, beside the law's class in its .cpp:
///   WEARSCALE_CONTACT_LAW(hooke, "one-line doc", [](const ContactLawInputs& in) { ... })
/// `key` is the name a case gives (`[dem] law = "key"`). The build collects
/// these lines (solvers/dem/CMakeLists.txt) into the table of contact_laws(),
/// so that a law in a static library is never dropped by the linker.
#define WEARSCALE_CONTACT_LAW(key, doc, ...)                                    \
  namespace wearscale::dem::registered {                                        \
  ContactLawEntry contact_law_##key() {                                         \
    return {#key, doc, [](const ContactLawInputs& inputs_) -> std::unique_ptr<ContactLaw> { \
              return (__VA_ARGS__)(inputs_);                                      \
            }};                                                                 \
  }                                                                             \
  }
