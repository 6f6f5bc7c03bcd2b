#pragma once
// The Cauchy stress (tension positive) averaged over a region of particles,
// from the virial (Morante et al. 2006), as the patch tests of §6.2 measure it:
//   σ = (1/V) [ Σ_{i∈R} W_i − Σ_{i∈R} m_i (v_i − v̄) ⊗ (v_i − v̄) ],
// W_i = ½ Σ_j (x_j − x_i) ⊗ f_ij the per-particle virial of the engine
// (f_ij the force of j on i), v̄ the region's mass-averaged velocity.
#include <cstddef>
#include <span>

#include "wearscale/dem/engine.hpp"
#include "wearscale/dem/simulation.hpp"

namespace wearscale::dem {

/// The stress of the particles `region` (indices) over the volume V they
/// fill. Needs sim.set_track_virial(true) and forces computed since the
/// particle set last changed (std::logic_error otherwise).
SymTensor virial_stress(const Simulation& sim, std::span<const std::size_t> region, double volume);
SymTensor virial_stress(const Engine& engine, std::span<const std::size_t> region, double volume);

/// The stress of the whole box (every particle, V = box volume): the stress
/// a periodic sample exerts on its boundaries.
SymTensor box_stress(const Simulation& sim);
SymTensor box_stress(const Engine& engine);

/// The largest |σ_aa| over the normal components (those a box rescaling
/// relaxes), and the largest |σ_ab| over all six.
double max_normal_stress(const SymTensor& s);
double max_stress(const SymTensor& s);

}  // namespace wearscale::dem
