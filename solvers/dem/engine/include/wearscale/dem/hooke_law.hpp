#pragma once
// The classic linear spring-dashpot contact of granular DEM (Cundall &
// Strack), as LAMMPS' pair gran/hooke/history computes it: repulsion only,
// normal force k_N δ − m_eff γ_N v_N, tangential spring with sliding history
// and damping m_eff γ_T v_T capped by Coulomb friction μ|F_N|.
#include "wearscale/dem/contact_law.hpp"

namespace wearscale::dem {

class HookeLaw final : public ContactLaw {
 public:
  HookeLaw(double normal_stiffness, double tangential_stiffness, double normal_damping, double tangential_damping,
           double coulomb)
      : k_n(normal_stiffness), k_t(tangential_stiffness), gamma_n(normal_damping), gamma_t(tangential_damping),
        friction(coulomb) {}

  double k_n = 0.0;      ///< normal stiffness [force/length]
  double k_t = 0.0;      ///< tangential stiffness [force/length]
  double gamma_n = 0.0;  ///< normal damping rate [1/time]
  double gamma_t = 0.0;  ///< tangential damping rate [1/time]
  double friction = 0.0; ///< Coulomb coefficient μ

  std::unique_ptr<ContactLaw> clone() const override { return std::make_unique<HookeLaw>(*this); }
  std::string_view name() const override { return "hooke"; }
  double pull_off_distance(double) const override { return 0.0; }
  /// √(2m/k_N) (6.6) of the lightest mobile particle.
  double critical_time_step(const Particles& p) const override;
  void add_pair_forces(PairLoop& loop) const override;
  void add_pair_energy(const Particles& p, std::size_t i, std::size_t j, std::size_t k, double delta,
                     const double* history, double& energy) const override;

  /// History doubles a pair keeps (the pair loop's fixed stride).
  static constexpr int history_doubles = 3;
  int history_size() const override { return history_doubles; }
  /// The pair force (pair_loop.hpp inlines it).
  PairForce contact(std::size_t k, const PairState& s, const double* history, double* updated, double dt,
                    bool advance) const;
};

}  // namespace wearscale::dem
