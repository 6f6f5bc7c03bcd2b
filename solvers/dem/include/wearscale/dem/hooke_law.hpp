#pragma once
// The classic linear spring-dashpot contact of granular DEM (Cundall &
// Strack), as LAMMPS' pair gran/hooke/history computes it: repulsion only,
// normal force k_N δ − m_eff γ_N v_N, tangential spring with sliding history
// and damping m_eff γ_T v_T capped by Coulomb friction μ|F_N|.
namespace wearscale::dem {

struct HookeLaw {
  double k_n = 0.0;      ///< normal stiffness [force/length]
  double k_t = 0.0;      ///< tangential stiffness [force/length]
  double gamma_n = 0.0;  ///< normal damping rate [1/time]
  double gamma_t = 0.0;  ///< tangential damping rate [1/time]
  double friction = 0.0; ///< Coulomb coefficient μ
};

}  // namespace wearscale::dem
