#pragma once
// Loose particles trapped between flat surfaces, thesis §7.3 (Figs. 7.8,
// 7.9): n circular (cylindrical across the thin depth) particles of diameter
// D, evenly spaced in a gap of height D between two flat SiO2 surfaces, the
// bottom wall fixed, the top wall pressed at p_N and dragged at v. At low p_N
// the particles roll (and merge into larger rolling ones): low tangential
// force. At high p_N they are crushed into a shear band of worn first-body
// material: high tangential force. The thesis finds the transition near
// p_N = 0.6 GPa for n = 3.
#include <functional>
#include <string>
#include <vector>

#include "wearscale/dem/sliding_cell.hpp"

namespace wearscale::dem {

struct TrappedParticlesSpec {
  SlidingCellSpec cell;      ///< L × W × H (H = D + both surfaces), d0, p_N, v, slide
  int count = 3;             ///< n loose particles (thesis: 2 to 4)
  double diameter = 0.0;     ///< D, also the height of the gap
  /// Clearance between the loose particles' outermost edges and the surfaces
  /// (in d0), so that no bond joins them initially: they are loose.
  double clearance = 0.25;
  /// The rigid-body fit of the loose particles runs from this fraction of the
  /// slide to its end (0: the whole slide; on long slides, where rolling
  /// particles merge, the last part shows the regime reached).
  double fit_from = 0.0;
};

struct TrappedParticlesResult {
  std::size_t particles = 0;
  std::vector<std::size_t> loose_particles;  ///< DEM particles in each loose particle
  double d_star = 0.0;                       ///< 32γG/σ_m,T² (6.65)
  double time_step = 0.0;
  long steps = 0;
  long relaxation_steps = 0;
  double area = 0.0;                         ///< A0 = L W
  std::vector<SlidingSample> history;        ///< the first row is the state before sliding
  double mean_pressure = 0.0;                ///< mean measured p_N over the second half of the slide
  double mean_tangential_force = 0.0;        ///< mean F_T over the second half
  double peak_tangential_force = 0.0;
  double friction = 0.0;                     ///< mean F_T / mean F_N over the second half
  /// Worn first-body particles at the end, and the thickness of first-body
  /// material they represent: their solid volume / (φ L W), φ the relaxed
  /// volume fraction (the shear band grows into the surfaces).
  std::size_t worn_first_body = 0;
  double band_thickness = 0.0;
  /// Kabsch misfit of each loose particle's original members over the fit
  /// window (0: it moved as a rigid body), and their mean.
  std::vector<double> loose_residual;
  double mean_residual = 0.0;
  /// "rolling" when the loose particles kept their identity (mean misfit
  /// < 1/3), else "shear band".
  bool rolling = false;
  std::string regime() const { return rolling ? "rolling" : "shear band"; }
};

using TrappedParticlesObserver = std::function<void(const SlidingCell&, const SlidingSample&, long step, long planned)>;

/// Builds the relaxed amorphous box (make_cell_sample) and runs the study.
TrappedParticlesResult run_trapped_particles(const TrappedParticlesSpec& spec, const TrappedParticlesObserver& observe = {},
                                             const RunCheckpoints& checkpoints = {});
/// The study on a given relaxed box (the same box for several pressures).
TrappedParticlesResult run_trapped_particles(const TrappedParticlesSpec& spec, const AmorphousSample& sample,
                                             const TrappedParticlesObserver& observe = {},
                                             const RunCheckpoints& checkpoints = {});

}  // namespace wearscale::dem
