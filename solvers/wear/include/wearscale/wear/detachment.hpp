#pragma once
// The detachment procedure of §5.1 on a micro-contact map sheared at σ_j:
//   1. take the largest candidate particle (crack criterion (4.25));
//   2. unload its contact points C and compute the drop ΔE_el (5.3);
//   3. if the energy balance holds (ΔE_el ≥ E_ad = π γ d² (4.16)–(4.18), γ
//      from d* by (4.35)) record the particle and keep C unloaded, else try
//      the next largest;
//   4. repeat until no candidate can detach.
// Candidates that overlap a recorded particle are not tried again.
//
// Energy bookkeeping (`cumulative`, default): the balance is that of all the
// particles recorded so far together, Σ ΔE_el ≥ Σ π γ d² — the energy left
// over by one particle helps the next one. This is the balance of ch. 4 for
// two separated particles (E_el,2 ≥ 2π γ d², C_n = 2, C_case = ½ in (4.48)),
// which the numerical model recovers (Fig. 5.4). `cumulative = false` asks
// each particle to pay for itself.
#include <atomic>
#include <cstddef>
#include <memory>
#include <vector>

#include "wearscale/wear/energy_release.hpp"

namespace wearscale::wear {

/// The shearing of the junctions and the material (ch. 4–5).
struct ShearedJunctions {
  double junction_strength = 1.0;  ///< σ_j, the uniform tangential traction on every contact point [Pa]
  double shear_modulus = 1.0;      ///< G [Pa]
  double poisson = 0.3;            ///< ν
  double tensile_strength = 1.0;   ///< σ_m of (4.25) [Pa]
  double spot = 0.05;              ///< crack sites within this fraction of each micro-contact's peak edge stress (crack_sites)
};

struct WearParticle {
  double x = 0.0, y = 0.0;         ///< centre [m], in [0, L)
  double diameter = 0.0;           ///< d [m]
  double volume = 0.0;             ///< π d³ / 6 [m³] (the sphere whose two hemispherical surfaces (4.16) cost)
  std::size_t contact_points = 0;  ///< points of C unloaded
  double energy_release = 0.0;     ///< ΔE_el (5.3) [J]
  double adhesive_energy = 0.0;    ///< π γ d² (4.16) [J]
};

struct DetachmentResult {
  std::vector<WearParticle> particles;
  double wear_volume = 0.0;          ///< Σ volumes [m³]
  double released_energy = 0.0;      ///< Σ ΔE_el of the recorded particles [J]
  std::size_t energy_evaluations = 0;  ///< ΔE_el computed in full (fast: self-energy used; naive: solves)
  std::size_t bound_rejections = 0;    ///< fast only: rejected by ΔE_el ≤ ΔA p_C·u without the self-energy
  std::size_t examined = 0;            ///< candidates the sequential procedure looks at (evaluated, bounded or blocked)
  std::size_t blocked = 0;             ///< of which skipped for overlapping a recorded particle (no ΔE_el needed)
  bool truncated = false;              ///< stopped by max_solves: the particles are incomplete
  std::size_t solves = 0;              ///< displacement updates (one per recorded particle) + full solves (one per candidate if naive)
  double largest_diameter() const;
};

enum class EnergyReleaseMethod { Fast, Naive };

struct DetachmentOptions {
  EnergyReleaseMethod method = EnergyReleaseMethod::Fast;
  bool cumulative = true;
  bool parallel = true;  ///< OpenMP threads (naive: over candidates; fast: in the sums and FFTs of each step); off inside an outer parallel loop over map pixels
  std::size_t max_solves = 0;  ///< naive only: stop after this many full solves (0: never), to time the baseline
};

/// γ = d* (2 − ν) σ_j² / (12 π G): the surface energy that gives the critical diameter d*   (4.35)
double surface_energy_for(double critical_diameter, const ShearedJunctions& junctions);

/// One sheared micro-contact map: its candidates, the displacement of the full
/// loading and the candidates' self-energies (computed on first use and kept),
/// shared by every d*.
class DetachmentModel {
 public:
  /// max_cells: largest candidate diameter in cells (0: n). InputError unless
  /// the grid has square cells; see crack_sites for the parameters.
  DetachmentModel(const MicroContactMap& map, const ShearedJunctions& junctions, long max_cells = 0);
  /// The same with the compliance of the map's grid and the junctions' G and ν
  /// made once and shared (its kernel tables are the costly part of a model:
  /// a wear map shares one over all its loads). InputError if it is another's.
  DetachmentModel(const MicroContactMap& map, const ShearedJunctions& junctions,
                  std::shared_ptr<const TangentialCompliance> compliance, long max_cells = 0);
  ~DetachmentModel();

  const MicroContactMap& map() const { return map_; }
  const std::vector<Disc>& candidates() const { return candidates_; }
  const CrackSites& sites() const { return sites_; }
  const EnergyRelease& energy_release() const { return release_; }
  /// E_el of the full loading (4.2) [J].
  double elastic_energy() const { return energy_; }
  /// u_x of the full loading.
  const RealField& displacement() const { return u0_; }

  /// The particles that detach for a critical diameter d* > 0 [m]. Thread-safe.
  DetachmentResult detach(double critical_diameter, const DetachmentOptions& options = {}) const;

 private:
  double self_energy(std::size_t candidate, const std::vector<std::uint8_t>& loaded, double loaded_count) const;
  MicroContactMap map_;
  ShearedJunctions junctions_;
  std::shared_ptr<const TangentialCompliance> compliance_;
  EnergyRelease release_;
  CrackSites sites_;
  std::vector<Disc> candidates_;
  std::vector<double> contact_count_;             // contact points in each candidate disc
  std::unique_ptr<std::atomic<double>[]> self_;   // self-energies, NaN until computed
  ColumnSegments cover_;  // the contact's cells by column, for the unloading sums
  RealField u0_;
  double energy_ = 0.0;
};

}  // namespace wearscale::wear
