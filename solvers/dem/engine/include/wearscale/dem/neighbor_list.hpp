#pragma once
// A half neighbour list (each pair once, under the lower index) built from a
// cell list with a skin, with per-pair tangential history that survives
// rebuilds. A pair is a particle, a neighbour and one periodic image of the
// neighbour (a byte: PeriodicImages): on a periodic axis thinner than the
// cutoff one neighbour may be met through several images, each its own
// contact with its own history, and a particle may meet its own images.
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "wearscale/core/checkpoint_state.hpp"
#include "wearscale/dem/box.hpp"
#include "wearscale/dem/cell_grid.hpp"
#include "wearscale/dem/particles.hpp"

namespace wearscale::dem {

struct NeighborSettings {
  double skin = 0.0;  ///< extra range beyond the interaction cutoff
  /// Rebuild every this many steps (0: only on displacement).
  int every = 0;
  /// Also rebuild when a particle has moved more than skin/2 since the last
  /// build (the list is then never stale).
  bool check_displacement = true;
  /// At a rebuild, carry over the tangential history of touching pairs only
  /// (r < r_i + r_j) and start every other pair afresh. This is what LAMMPS'
  /// fix neigh/history does for a granular pair style that does not set
  /// `beyond_contact`, as the thesis' gran/cohesive/history (§6.1); it drops
  /// the springs of the cohesive pairs at a rate set by the skin, so results
  /// depend on a numerical parameter. A compatibility switch, to reproduce
  /// the thesis' runs (bench/dem/thesis_lammps/README.md); off by default.
  bool history_of_touching_pairs_only = false;
  /// Renumber the particles in cell order (cell_order.hpp) at the first
  /// build and then at every this many builds (0: never), the pairs and
  /// their histories with them, so that a system whose particles flow keeps
  /// its pairs close in index (Simulation: the user's numbering is kept
  /// outside its calls).
  int renumber_every = 0;
};

class NeighborList {
 public:
  /// Builds the list for pairs closer than r_i + r_j + reach + skin, skipping
  /// pairs of particles of the same wall (two walls do interact). Periodic
  /// coordinates must be wrapped into the box, and p.image count the periods
  /// each particle was wrapped by. The history of contacts present before is
  /// kept: the same particles and the same image once the wraps since the
  /// last build are undone; a particle's image may change by less than
  /// max_wraps periods a component between two builds (Simulation refuses
  /// more: a particle that went that far in a build's interval has missed
  /// its contacts anyway). InputError when a periodic length is shorter than
  /// the largest particle diameter (a particle would overlap itself).
  /// `history_size` doubles of history per pair (the contact law's); the
  /// histories are carried over only between builds of the same size.
  void build(const Particles& p, const Box& box, double reach, double skin, int history_size = 3);
  /// The particles were renumbered, old i becoming new_index[i] (a
  /// permutation of the list's particles): every pair moves to the row of
  /// its lower new index, and when its two particles swapped sides it takes
  /// the mirrored image and its history goes through `reverse` (the history
  /// of (j, i) from that of (i, j)); the rows are sorted as a build sorts
  /// them, and the positions and images of the last build follow their
  /// particles. The next build then carries the histories over as after any
  /// other build.
  void renumber(std::span<const std::uint32_t> new_index, const std::function<void(double*)>& reverse);
  /// The periods a particle may be wrapped by between two builds, exclusive.
  static constexpr int max_wraps = 128;
  /// NeighborSettings::history_of_touching_pairs_only, for the next builds.
  void set_history_of_touching_pairs_only(bool on) { touching_only_ = on; }
  bool history_of_touching_pairs_only() const { return touching_only_; }
  /// Keep the positions of the last build for moved_beyond_half_skin() (24
  /// bytes a particle); NeighborSettings::check_displacement. Without them
  /// moved_beyond_half_skin() is always true.
  void set_keep_build_positions(bool on) { keep_positions_ = on; }

  std::size_t pairs() const { return neighbor_.size(); }
  const std::vector<std::uint32_t>& offsets() const { return offset_; }
  const std::vector<std::uint32_t>& neighbors() const { return neighbor_; }
  const std::vector<std::uint8_t>& shifts() const { return shift_; }
  /// Doubles of history per pair.
  int history_size() const { return history_size_; }
  /// Tangential history, history_size() per pair, in list order.
  std::vector<double>& history() { return history_; }
  const std::vector<double>& history() const { return history_; }

  /// The images the shift indices of the last build refer to.
  const PeriodicImages& images() const { return images_; }
  /// Their separation offsets for this box (images().count() of them).
  void shift_vectors(const Box& box, Vec3* out) const { images_.vectors(box, out); }

  /// Largest displacement since the last build exceeds half the skin (true
  /// when the build's positions were not kept).
  bool moved_beyond_half_skin(const Particles& p) const;
  long builds() const { return builds_; }
  /// Forgets all pairs and histories.
  void clear();

  /// The pairs, their images and histories and the positions at the last
  /// build, under `prefix` in a checkpoint, bit for bit (a restored list is
  /// the one saved, not a rebuild, so a resumed run sums its forces in the
  /// same order).
  void save(CheckpointState& out, const std::string& prefix) const;
  /// InputError naming the entry when the checkpoint does not fit
  /// `particles` (whose images, unchanged since the saved build, are those
  /// of the build). A list saved without its images' reach (DEM state format
  /// 1) used the 27 nearest images.
  void restore(const CheckpointState& in, const std::string& prefix, const Particles& particles,
               int history_size = 3);

 private:
  void search(const Particles& p, const Box& box, double range, double max_radius, int threads);
  void sort_rows(int threads);
  void carry_history(const Particles& p, const Box& box, int threads);
  static std::array<std::uint8_t, 3> image_low_bytes(const std::array<std::int32_t, 3>& image) {
    return {static_cast<std::uint8_t>(image[0]), static_cast<std::uint8_t>(image[1]),
            static_cast<std::uint8_t>(image[2])};
  }

  std::vector<std::uint32_t> offset_, neighbor_;
  std::vector<std::uint8_t> shift_;
  std::vector<double> history_;
  PeriodicImages images_;
  // Previous list's pairs, for carrying the histories (kept in history_
  // until they move) over a rebuild; its arrays are reused by the next build.
  std::vector<std::uint32_t> old_offset_, old_neighbor_;
  std::vector<std::uint8_t> old_shift_;
  PeriodicImages old_images_;
  // A row of the list (of the previous one) holds a neighbour through more
  // than one image: the carry-over then checks its moves' order.
  bool several_images_ = true, old_several_images_ = true;
  // Scratch reused between builds: each thread's search results (search());
  // each row's count, then its cursor, and the carry-over's flags are in
  // the grid's scratch(). A stream on cache lines of its own:
  // its vectors' ends move at every pair its thread finds, and two streams
  // sharing a line would bounce it between the cores at each of them.
  // The search appends through plain pointers into room made for a whole
  // run of candidates, so a stream's vectors are as long as the most a build
  // needed and its counts say how much of them this build found.
  struct alignas(64) Stream {
    std::vector<std::uint32_t> neighbor;  // the home particles' pairs with higher indices, in order
    std::vector<std::uint8_t> shift;
    struct Home {
      std::uint32_t i, pairs;
    };
    std::vector<Home> home;
    struct Pair {
      std::uint32_t i, j;
      std::uint8_t shift;
    };
    std::vector<Pair> other;  // pairs under a lower index than the home particle's
    std::size_t pairs = 0, homes = 0, others = 0;
    std::span<const Home> homes_found() const { return {home.data(), homes}; }
    std::span<const Pair> others_found() const { return {other.data(), others}; }
  };
  std::vector<Stream> streams_;
  // Scratch of renumber(): the old pair at each new slot.
  std::vector<std::uint32_t> renumber_source_;
  CellGrid grid_;
  std::vector<float> sorted_radius_;  // the radii in the grid's cell order (half-stencil grids)
  std::vector<Vec3> built_at_;
  // p.image at the last build modulo 256 (3 bytes, not 12): the wraps since
  // then are the difference modulo 256, exact below max_wraps.
  std::vector<std::array<std::uint8_t, 3>> built_image_;
  int history_size_ = 3;
  double half_skin_ = 0.0;
  long builds_ = 0;
  bool touching_only_ = false;
  bool keep_positions_ = true;
};

}  // namespace wearscale::dem
