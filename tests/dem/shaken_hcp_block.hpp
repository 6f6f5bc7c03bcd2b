#pragma once
// A periodic HCP block of touching spheres (d = 100, within [d_min, d_c] of
// Table 6.4, so second neighbours stay beyond δ_f and the lattice is at
// equilibrium) shaken by small random velocities: the test bed of the
// dynamics tests, deep or one diameter thin.
#include <random>
#include <utility>
#include <variant>

#include "wearscale/dem/cohesive_law.hpp"
#include "wearscale/dem/hcp_lattice.hpp"
#include "wearscale/dem/simulation.hpp"

namespace wearscale::dem::test_support {

inline double critical_step(const Simulation& s) {
  return s.law_as<CohesiveLaw>().critical_time_step(s.particles());
}

// `material`'s law on the lattice with nx × ny × nz cells of spheres of
// diameter 100, velocities up to 0.02 per component from `seed`, the time
// step a fraction of the critical one.
inline Simulation shaken_hcp_block(int nx, int ny, int nz, const CohesiveMaterial& material, double step_fraction,
                                   unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double radius = 50.0;
  HcpLattice lattice{2.0 * radius, nx, ny, nz};
  Particles p;
  for (const auto& x : lattice.sites()) p.add({x, radius, 1.0, {0.02 * u(rng), 0.02 * u(rng), 0.02 * u(rng)}, 0, 0});
  Simulation sim(std::move(p), lattice.box(), CohesiveLaw({material}), NeighborSettings{2.0, 0, true});
  sim.set_time_step(step_fraction * critical_step(sim));
  return sim;
}

}  // namespace wearscale::dem::test_support
