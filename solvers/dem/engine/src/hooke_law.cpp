#include "wearscale/dem/hooke_law.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "wearscale/dem/cohesive_law.hpp"
#include "wearscale/dem/hooke_kernel.hpp"
#include "wearscale/dem/pair_loop.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/dem/particles.hpp"

namespace wearscale::dem {

// LAMMPS pair gran/hooke/history, term by term (so that the benchmark does
// the same work and the same arithmetic as the reference decks): the kernel
// shared with the LAMMPS pair style wearscale/hooke.
inline PairForce HookeLaw::contact(std::size_t, const PairState& s, const double* hist, double* updated, double dt,
                                   bool advance) const {
  return hooke_contact({k_n, k_t, gamma_n, gamma_t, friction}, s, hist, updated, dt, advance);
}

void HookeLaw::add_pair_forces(PairLoop& loop) const { run_pair_loop(*this, loop); }

double HookeLaw::critical_time_step(const Particles& p) const {
  double lightest = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.wall[i] == no_wall) lightest = std::min(lightest, p.mass[i]);
  return dem::critical_time_step(lightest, k_n);  // (6.6)
}

void HookeLaw::add_pair_energy(const Particles&, std::size_t, std::size_t, std::size_t, double delta,
                               const double* h, double& e) const {
  if (delta < 0.0) e += 0.5 * k_n * delta * delta;
  e += 0.5 * k_t * (h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
}

}  // namespace wearscale::dem

// From a case: the springs and dampers of the cohesive law (6.54)-(6.60)
// for two particles of the first material at the case's diameter d0, without
// cohesion, and Coulomb friction μ = `friction` in place of the cap (6.5).
WEARSCALE_CONTACT_LAW(hooke, "linear spring-dashpot with Coulomb friction (LAMMPS gran/hooke/history)",
                      [](const ContactLawInputs& in) {
                        using namespace wearscale::dem;
                        if (in.materials.empty() || !(in.diameter > 0.0))
                          throw wearscale::InputError("the hooke DEM law needs a material and a diameter d0 > 0");
                        const auto& m = in.materials.front();
                        const double r = 0.5 * in.diameter;
                        const double mass = m.density * 4.0 / 3.0 * std::numbers::pi * r * r * r;
                        const CohesivePair p = cohesive_pair(m, r, r, mass, mass);
                        const double m_eff = 0.5 * mass;
                        return std::make_unique<HookeLaw>(p.k_n, p.k_t, p.c_n / m_eff, p.c_t / m_eff, in.friction);
                      })
