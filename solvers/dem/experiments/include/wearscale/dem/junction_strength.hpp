#pragma once
// The junction study of thesis §7.1.1 (Fig. 7.1, 7.2): a quasi-2D periodic
// HCP cell, two surfaces joined by one junction of initial size D across the
// sliding direction, the bottom wall fixed, the top wall pressed at p_N and
// dragged at v. It measures the peak and steady tangential stress p_T (wall
// force over the cell area A0 = L B), the contact ratio A/A0 before and after
// sliding, and whether the junction was flattened, sheared or detached. From
// a set of such runs, fit_junction_law() fits the model of §7.1.2: σ of
// p_T = (A/A0) σ (7.9), p_crit of A/A0 = p_N/p_crit (7.6) and μ0 of
// p_T,min = μ0 p_N (7.10).
//
// Two materials: the top half of the junction and the top surface are the
// pin material, the rest the disc material; pairs across the interface use
// dem::mix (springs in series for E, the weaker strengths, Berthelot for γ,
// arithmetic means for ν, η, ρ, s — see cohesive_material.hpp).
#include <functional>
#include <string>
#include <vector>

#include "wearscale/dem/run_checkpoints.hpp"
#include "wearscale/dem/cohesive_material.hpp"
#include "wearscale/dem/sheared_junction.hpp"

namespace wearscale::dem {

class Engine;

/// The periodic cell. Thesis: 37.5 × 37.5 × 2.4 nm³ with d0 = 1.5 nm, i.e.
/// 25 rows along x, ≈ 14 double rows (√3 d0) in height, one HCP cell
/// (√(8/3) d0 = 2.45 nm, two close-packed layers) across: each particle meets
/// the three of the other layer through two periodic images. The
/// close-packed planes are the x–z planes, so slip rows run along the
/// sliding direction x.
struct JunctionCell {
  double d0 = 1.5e-9;     ///< particle diameter (HCP nearest-neighbour distance)
  int length = 25;        ///< L in d0 (periodic sliding direction x)
  int height = 14;        ///< cell height in HCP double rows of √3 d0 (z, normal)
  int depth = 1;          ///< HCP cells of √(8/3) d0 across (y, periodic)
  double gap = 0.25;      ///< height of the gap the junction bridges, as a fraction of the cell height
  double wall_thickness = 1.5;  ///< in d0: the particles within it of the top and bottom faces form the rigid walls
};

/// How the cell's particles are arranged: the HCP lattice of §7.1.1 (an
/// ordered, crystalline solid), or an amorphous sample (§6.2.2, sizes
/// 0.75-1.25 d0) of the same size — the weakened, amorphous state of a
/// material that the thesis suggests for Si (§9.3.3) and the arrangement of
/// amorphous SiO2 itself.
enum class Arrangement { Hcp, Amorphous };

struct JunctionStrengthSpec {
  CohesiveMaterial top;     ///< pin material (top surface, upper half of the junction)
  CohesiveMaterial bottom;  ///< disc material
  JunctionCell cell;
  Arrangement arrangement = Arrangement::Hcp;
  /// Amorphous only: the sample's seed and its relaxation (§6.2.2), phase 2
  /// ending at this stress (in E) or after this many steps.
  unsigned seed = 1;
  double relax_tolerance = 1e-4;
  long max_relax_steps = 20000;
  double contact_ratio = 1.0;   ///< initial D/L, (0, 1]; 1: the surfaces are one solid
  double pressure = 0.0;        ///< p_N on the top wall [Pa]
  double velocity = 10.0;       ///< sliding velocity of the top wall [m/s]
  double time_step = 0.1;       ///< in Δt_c (thesis: 0.1, no global damping)
  double settle_distance = 0.1; ///< loading before sliding: the time to slide this many L at v
  double sliding_distance = 1.0;///< in L
  double steady_from = 0.5;     ///< the steady window: the last (1 − steady_from) of the slide
  long record_every = 200;      ///< steps per sample of the history (forces averaged over them)
  /// Carry tangential histories over neighbour rebuilds for touching pairs
  /// only, as LAMMPS did in the thesis' runs (NeighborSettings); off: every
  /// contact keeps its history, as (6.4) defines it.
  bool history_of_touching_pairs_only = false;
  /// The engine that integrates the run (engine.hpp: "wearscale", "lammps").
  std::string engine = "wearscale";
};

struct JunctionStrengthResult {
  enum class Outcome { Flattened, Sheared, Detached };
  double length = 0.0, depth = 0.0, height = 0.0, gap = 0.0;  ///< L, B, cell height, gap [m]
  std::size_t particles = 0, junction_particles = 0;
  double time_step = 0.0;
  long steps = 0;
  double initial_contact_ratio = 0.0;  ///< D/L as built (whole columns of particles)
  double loaded_contact_ratio = 0.0;   ///< A/A0 after loading, before sliding
  double final_contact_ratio = 0.0;    ///< A/A0 at the end of the slide
  double peak_tangential = 0.0;        ///< peak p_T [Pa]
  double steady_tangential = 0.0;      ///< mean p_T over the steady window [Pa]
  double normal = 0.0;                 ///< mean measured p_N over the slide [Pa]
  /// Rigid 2D motion of the junction over the steady window: rotation about y
  /// times D_final / slide (≈ 1 for rolling without slip), and RMS misfit over
  /// RMS displacement (small for a rigid body).
  double rolling_rate = 0.0, rigid_residual = 0.0;
  Outcome outcome = Outcome::Sheared;
  std::vector<JunctionSample> history;  ///< forces per sample, averaged over record_every steps

  /// "flattened" (A grew by more than two particles and 20 %), "detached" (it turns as a
  /// rigid rolling body), else "sheared" (kept its size, slid on its interface).
  std::string verdict() const;
};

/// Called after each sample (progress, dumps).
using JunctionStrengthObserver = std::function<void(const Engine&, const JunctionSample&, long step, long planned)>;

JunctionStrengthResult run_junction_strength(const JunctionStrengthSpec& spec,
                                             const JunctionStrengthObserver& observe = {},
                                             const RunCheckpoints& checkpoints = {});

/// The measured contact ratio: the fraction of the cell length covered by
/// the diameters of mobile particles centred within d0/2 of `z_mid`.
double contact_ratio_at(const Engine& sim, double z_mid, double d0);

/// One junction run reduced to what the fit uses.
struct JunctionPoint {
  double pressure = 0.0;        ///< p_N imposed
  double initial_ratio = 0.0;   ///< D/L
  double loaded_ratio = 0.0;    ///< A/A0 before sliding
  double final_ratio = 0.0;     ///< A/A0 after sliding
  double peak = 0.0;            ///< peak p_T
  double steady = 0.0;          ///< steady p_T
  bool flattened = false;
};

/// The model of §7.1.2 fitted to a set of runs (least squares through the
/// origin), with relative RMS residuals as fit quality.
struct JunctionLawFit {
  /// σ of peak p_T = (A/A0) σ (7.9): on the runs not flattened, at their
  /// loaded A/A0; if all were flattened, on all runs at their final A/A0.
  double shear_strength = 0.0;
  double shear_strength_rms = 0.0;
  double full_contact_peak = 0.0;    ///< mean peak p_T of the D = L runs (0: none)
  /// σ_steady of steady p_T = (A/A0) σ_steady: the sliding strength, over the
  /// D = L runs if any (else over the σ runs).
  double steady_strength = 0.0;
  /// Of A/A0_loaded = p_N/p_crit (7.6) on the runs the load crushed before
  /// sliding (loaded A/A0 > 1.2 D/L, and < 0.95: a junction crushed into full
  /// contact only says p_crit ≤ p_N). Spreading while sliding (junctions
  /// below d*) is left aside, as in the model.
  double p_crit = 0.0;
  double p_crit_rms = 0.0;
  /// Where p_crit came from: "runs crushed by the load" or, when none
  /// qualifies, "σ_m,c = σ (7.5)": the thesis' assumption that the
  /// compressive strength equals the fitted shear strength.
  std::string p_crit_source;
  /// μ0 = σ_steady/p_crit (9.13), the slope of p_T,min = μ0 p_N (7.10).
  double mu0 = 0.0;
  /// Steady p_T/p_N measured on the crushed runs (a diagnostic: their
  /// junctions may grow further while sliding). 0 without crushed runs.
  double mu0_direct = 0.0;
  std::size_t runs = 0;
  std::size_t flattened = 0;  ///< flattened by the end of the slide
  std::size_t saturated = 0;  ///< of those, into full contact
  std::size_t crushed = 0;    ///< crushed by the load before sliding: the p_crit runs
};

/// InputError when there is no run or no run has a peak p_T > 0.
JunctionLawFit fit_junction_law(const std::vector<JunctionPoint>& points);

}  // namespace wearscale::dem
