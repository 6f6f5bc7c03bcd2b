#pragma once
// The reversible cohesive pair force of thesis §6.1: Hookean repulsion and
// cohesion up to δ_e, linear softening to δ_f (6.3), an elastic tangential
// spring capped by F'_m,T (6.4)-(6.5), viscous damping (6.2), with parameters
// derived from the material and the pair's radii and masses (6.49)-(6.61).
#include <cstddef>
#include <string>
#include <vector>

#include "wearscale/dem/cohesive_material.hpp"
#include "wearscale/dem/contact_law.hpp"

namespace wearscale::dem {

class Particles;

/// The seven force parameters of one pair (Table 6.2).
struct CohesivePair {
  double k_n = 0.0;      ///< normal stiffness k_N (6.54)
  double k_t = 0.0;      ///< tangential stiffness k_T (6.55)
  double delta_e = 0.0;  ///< end of the linear range, min(δ_e, δ_f) (6.56)
  double delta_f = 0.0;  ///< fracture separation δ_f (6.57)
  double f_mt = 0.0;     ///< maximum tangential force F_m,T (6.58)
  double c_n = 0.0;      ///< normal damping c_N (6.59)
  double c_t = 0.0;      ///< tangential damping c_T (6.60)
};

/// A_N = √2 r² / (1 − 2ν)   (6.51)
double normal_cross_section(double r_eff, double poisson);
/// A_T = √2 r² (1 − 4ν) / ((1 − 2ν)(1 + ν))   (6.52)
double tangential_cross_section(double r_eff, double poisson);
/// δ_e = (r_i + r_j) σ_m,N / E   (6.56)
double elastic_separation(const CohesiveMaterial& m, double radius_sum);
/// δ_f = 4γ/σ_m,N if r_i + r_j ≤ d_c, else δ_e ((r_i + r_j)/d_c)^(−s)   (6.57)
double fracture_separation(const CohesiveMaterial& m, double radius_sum);

/// All parameters of a pair (6.53)-(6.61). For r_i + r_j > d_c, δ_f < δ_e:
/// the force stays Hookean up to δ_f and then vanishes, so the matched
/// strength is σ_m,N ((r_i + r_j)/d_c)^(−s) (6.63) and, for s = ½, the
/// fracture energy is still 2γA_N (Fig. 6.5). F_m,T = A_T σ_m,T (6.58) at
/// every size.
CohesivePair cohesive_pair(const CohesiveMaterial& m, double r_i, double r_j, double m_i,
                           double m_j);

/// F_N(δ_N) of (6.3); positive is attractive, negative repulsive.
double normal_force(const CohesivePair& p, double delta_n);
/// F'_m,T = min((δ_f − δ_N)/δ_f, 1) F_m,T   (6.5)
double tangential_cap(const CohesivePair& p, double delta_n);
/// The energy stored in the normal spring, zero at and beyond δ_f:
/// dU/dδ_N = F_N.
double normal_energy(const CohesivePair& p, double delta_n);

/// The smallest spacing d of an HCP lattice of this material whose second
/// neighbours, √2 d apart (a gap of (√2 − 1) d), stay beyond the cohesive
/// reach δ_f (6.57) when compressed by `strain`. Closer, they attract in the
/// softening branch of (6.3), a negative stiffness, and the lattice's
/// measured E and ν are nonsense (Table 6.4: δ_f = 30, d ≥ 72.4 at rest,
/// 75.0 under the patch test's 1 %; the thesis' lattices start at 0.6 d_c =
/// 90). Infinite when no spacing qualifies.
double smallest_hcp_spacing(const CohesiveMaterial& m, double strain = 0.0);
/// InputError when an HCP lattice of spacing `d0` made of `materials` (and
/// their interfaces, mix()) compressed by `strain` would put second
/// neighbours within δ_f: names the gap, the reach and the smallest valid
/// d0. `what` names the study.
void require_hcp_spacing(const std::vector<CohesiveMaterial>& materials, double d0, const std::string& what,
                         double strain = 0.0);

/// Δt_c = √(2m/k_N)   (6.6)
double critical_time_step(double mass, double k_n);
/// c_c = √(2 k_N m)   (6.64)
double critical_damping(double mass, double k_n);

/// The force law over a table of materials (a particle's material tag indexes
/// it); pairs of two materials use mix() unless their interface is given.
class CohesiveLaw final : public ContactLaw {
 public:
  explicit CohesiveLaw(std::vector<CohesiveMaterial> materials);
  /// The targets of the pairs of materials a and b (both orders) in place of
  /// mix(): an interface stated on its own, as LAMMPS' pair_coeff i j does.
  /// InputError if it cannot be modelled or a tag is out of the table.
  void set_interface(std::size_t a, std::size_t b, const CohesiveMaterial& interface);

  /// Cohesion (δ_N > 0 branch of (6.3)) and the tangential force can be
  /// switched off, as in the relaxation of an amorphous sample (§6.2.2).
  bool cohesion = true;
  bool tangential = true;

  const std::vector<CohesiveMaterial>& materials() const { return materials_; }
  const CohesiveMaterial& pair_material(std::size_t a, std::size_t b) const {
    return mixed_[a * materials_.size() + b];
  }
  CohesivePair pair(const Particles& p, std::size_t i, std::size_t j) const;
  /// The longest interaction range beyond contact, max δ_f, for particles of
  /// at most `max_radius`.
  double reach(double max_radius) const;
  /// The smallest critical time step (6.6) over the particles (against
  /// themselves: the stiffest, lightest pairs).
  double critical_time_step(const Particles& p) const override;
  /// c_c (6.64) of the smallest particle.
  double critical_damping(const Particles& p) const;

  std::unique_ptr<ContactLaw> clone() const override { return std::make_unique<CohesiveLaw>(*this); }
  std::string_view name() const override { return "cohesive"; }
  /// δ_f (6.57) with cohesion, 0 without.
  double pull_off_distance(double max_radius) const override { return cohesion ? reach(max_radius) : 0.0; }
  /// The pairs' parameters (6.53)-(6.61), once per build.
  void prepare(const Particles& p, const NeighborList& list) override;
  void add_pair_forces(PairLoop& loop) const override;
  void add_pair_energy(const Particles& p, std::size_t i, std::size_t j, std::size_t k, double delta,
                     const double* history, double& energy) const override;

  /// History doubles a pair keeps (the pair loop's fixed stride).
  static constexpr int history_doubles = 3;
  int history_size() const override { return history_doubles; }
 private:
  CohesivePair listed_pair(std::size_t k) const;

  std::vector<CohesiveMaterial> materials_;
  std::vector<CohesiveMaterial> mixed_;
  // The listed pairs' parameters from prepare(): one set when every particle
  // has the same material, radius and mass, else one per listed pair as
  // structure of arrays (the vectorised pair loop reads them contiguously).
  bool uniform_ = false;
  CohesivePair uniform_pair_;
  std::vector<double> k_n_, k_t_, delta_e_, delta_f_, f_mt_, c_n_, c_t_;
};

}  // namespace wearscale::dem
