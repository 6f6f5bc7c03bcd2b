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
#include <cstdint>
#include <vector>

#include "wearscale/wear/candidate_particles.hpp"
#include "wearscale/wear/tangential_compliance.hpp"

namespace wearscale::wear {

/// Sums of mask·value over the cells of a disc in O(diameter): prefix sums
/// along x on every row.
class DiscSums {
 public:
  explicit DiscSums(const Grid2D& grid);
  /// values == nullptr counts the masked cells.
  void build(const std::vector<std::uint8_t>& mask, const RealField* values);
  double sum(const Disc& disc) const;

 private:
  Grid2D grid_;
  std::vector<double> prefix_;  // per row j: nx + 1 prefix sums over x
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
  /// still loaded (u elsewhere is left stale): a sum over the kernel when C is
  /// small, one padded solve otherwise. Returns the number of cells unloaded.
  std::size_t unload(const Disc& disc, std::vector<std::uint8_t>& loaded, RealField& u, RealField& scratch_p,
                     RealField& scratch_u, TangentialCompliance::Workspace& w) const;

 private:
  const TangentialCompliance* f_;
  double sigma_j_;
};

}  // namespace wearscale::wear
