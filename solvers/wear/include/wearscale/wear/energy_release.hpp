#pragma once
// The elastic energy released by unloading the contact points C of a candidate
// particle (5.3), not the local estimate ½∫_C p u of Popov & Pohrt:
//   ΔE_el = ½∫_C p u + ½∫_{Ω∖C} p (u − u') = ΔA p_C·u − ½ ΔA p_C·(F p_C),
// with u = F p the displacement of the present loading and F the x → x
// compliance. The first term is a sum over C of the u computed once per
// loading state; the second, the self-energy of the traction on C, does not
// depend on the rest of the map. Two evaluators: the fast one (this
// decomposition, self-energy from the real-space kernel G or a small FFT of
// the disc's box) and the naive one (a full solve of p − p_C per candidate).
#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "wearscale/wear/candidate_particles.hpp"
#include "wearscale/wear/tangential_compliance.hpp"

namespace wearscale::wear {

/// Sums of mask·value over the cells of a disc in O(diameter): prefix sums
/// along x on every row, stored column after column (building them reads and
/// writes contiguous memory) in blocks of rows that can be brought up to date
/// alone: after a change of the mask or values, only the rows of the discs
/// asked about are summed again.
class DiscSums {
 public:
  explicit DiscSums(const Grid2D& grid);
  /// Sums `mask`·`values` (values == nullptr counts the masked cells) over
  /// every row. Both are kept by reference for stale() and prepare().
  void build(const std::vector<std::uint8_t>& mask, const RealField* values);
  /// The mask or values given to build() changed: every row is out of date.
  void stale();
  /// Brings the rows of the disc up to date (not thread-safe).
  void prepare(const Disc& disc);
  /// Σ over the disc; its rows must be up to date (build() or prepare()). Thread-safe.
  double sum(const Disc& disc) const;

 private:
  static constexpr std::size_t kBlock = 16;  // rows summed together
  void build_block(std::size_t block);
  Grid2D grid_;
  std::vector<double> prefix_;  // (nx + 1) × ny: prefix_[m ny + j] = Σ_{i < m} over row j
  std::vector<std::uint8_t> fresh_;  // per block of kBlock rows
  const std::vector<std::uint8_t>* mask_ = nullptr;
  const RealField* values_ = nullptr;
};

/// Cells of each column i of a mask (fixed x, contiguous in memory) as
/// segments [j0, j1) whose ends are multiples of 8 (up to the kernel's padded
/// ny), joined across gaps of fewer than 8 cells: what the kernel sums of
/// EnergyRelease::unload() run over. A cover of the mask's cells and of any
/// mask within it (the cells unloaded since stay inside).
struct ColumnSegments {
  ColumnSegments(const Grid2D& grid, const std::vector<std::uint8_t>& mask);
  std::vector<std::size_t> first;         ///< per column i: its segments are spans[first[i] … first[i + 1])
  std::vector<std::pair<long, long>> spans;
  std::size_t cells = 0;                  ///< Σ of the segments' lengths
};

/// Fields of the grid for one full solve (traction, displacement, the padded
/// workspace), each made on first use. One per thread.
class SolveScratch {
 public:
  explicit SolveScratch(const TangentialCompliance& compliance) : f_(&compliance) {}
  RealField& traction();
  RealField& displacement();
  TangentialCompliance::Workspace& workspace();

 private:
  const TangentialCompliance* f_;
  std::optional<RealField> p_, u_;
  std::optional<TangentialCompliance::Workspace> w_;
};

class EnergyRelease {
 public:
  EnergyRelease(const TangentialCompliance& compliance, double junction_strength);

  const TangentialCompliance& compliance() const { return *f_; }
  double junction_strength() const { return sigma_j_; }

  /// ½ ΔA p_C·(F p_C) with p_C = σ_j on the loaded cells of the disc: the
  /// direct double sum over G when C is small, the autocorrelation of C by an
  /// FFT of its (padded) box otherwise. Thread-safe.
  double self_energy(const Disc& disc, const std::vector<std::uint8_t>& loaded) const;

  /// ΔE_el (5.3) from W_C = ΔA σ_j Σ_C u (e.g. σ_j ΔA · DiscSums over loaded·u) and the self-energy.
  static double release(double work, double self_energy) { return work - self_energy; }

  /// The naive baseline: E(p) − E(p − p_C), with E(p − p_C) from a full solve.
  /// `energy` is E(p) of the present loading; the fields are scratch of the grid.
  double naive_release(const Disc& disc, const std::vector<std::uint8_t>& loaded, double energy, RealField& traction,
                       RealField& u, TangentialCompliance::Workspace& w) const;

  /// The traction p = σ_j on the loaded cells.
  void traction(const std::vector<std::uint8_t>& loaded, RealField& p) const;

  /// Unloads the disc: loaded cells of C → 0 and u ← u − F p_C on the cells
  /// still loaded (u elsewhere is left stale): sums over the kernel for each
  /// run of C along x when that is cheaper, one padded solve otherwise.
  /// Returns the number of cells unloaded.
  /// `cover`: segments covering the loaded cells (e.g. of the contact before
  /// any unloading), made from `loaded` if null.
  std::size_t unload(const Disc& disc, std::vector<std::uint8_t>& loaded, RealField& u, SolveScratch& scratch,
                     const ColumnSegments* cover = nullptr) const;

 private:
  void subtract_run_sums(const std::vector<std::array<long, 3>>& runs, const ColumnSegments& cover,
                         std::size_t remaining, RealField& u) const;
  const TangentialCompliance* f_;
  double sigma_j_;
};

}  // namespace wearscale::wear
