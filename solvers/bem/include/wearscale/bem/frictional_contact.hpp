#pragma once
// Frictional contact of a rigid surface on a periodic elastic flat (Appendix
// A): imposed mean normal and tangential tractions, Coulomb (A.2) or Tresca
// (A.3) friction, all three traction components solved together through the
// Boussinesq–Cerruti tensor, so normal and tangential are coupled for ν < 0.5
// and decoupled for ν = 0.5.
//
// Conventions (as HalfSpace and NormalContact): z points into the solid; the
// rigid body presses with p_N = p_z ≥ 0 and drags with p_T = (p_x, p_y);
// heights h are positive towards the elastic body. The normal gap is
// g_N = u_z − h + d and the slip g_T = u_T − δ_T, with d and δ_T the rigid
// normal and tangential displacements (the multipliers of the imposed means).
// At the solution every point is open (p = 0, g_N ≥ 0), sticking
// (‖p_T‖ < p_T,max, g_T = 0) or sliding (‖p_T‖ = p_T,max, g_T = −λ p_T, λ ≥ 0).
//
// Algorithm 1 of the thesis, a projected conjugate gradient on p:
//  - the gradient (A.13) is the gap, shifted to zero mean on the contact
//    (normal) and on the stick zone I_s (tangential: the shift is δ_T);
//  - two conjugate sequences, one for p_N (Polonsky–Keer) and one for p_T,
//    with step lengths minimising the quadratic model over both together
//    (the normal–tangential coupling term comes from the Fourier spectra);
//  - a point on the friction cone keeps p_T on it and only turns its p_T
//    (the cone's curvature, ‖g_T‖/p_T,max, enters the step length); one that
//    slides the wrong way (g_T·p_T > 0) is released into the stick zone;
//  - after each step p is brought back into the friction cone: p_N ≥ 0 with
//    penetrating points re-admitted (Polonsky–Keer), p_N rescaled to its mean
//    (A.8c), p_T projected on the discs ‖p_T‖ ≤ p_T,max with its mean imposed
//    by one shift of the free (non-sliding) points.
// The friction bound p_T,max is lagged: each subproblem is solved with a fixed
// bound (μ p_N of the previous one, or σ_m,T on the previous contact), then
// the bound is updated, until it changes by less than the tolerance (a
// fixed point, as in Panagiotopoulos' scheme). This replaces the μ‖g_T‖ term
// of (A.13): that term compensates the dilatancy of a projection orthogonal
// to the cone, while our projection is at fixed p_N and has none.
// Tresca with ν < 0.5 may not settle: a point entering a micro-contact
// carries σ_m,T at once, whose normal displacement (4.22) can lift a
// neighbour off, which lifts it back... After 8 updates without progress the
// last bound is kept (FrictionalResult::unsettled_points says how many points
// differ from the law).
// Coupled contact close to full sliding, with a stick zone of a few cells,
// may lose its stick zone again and again: NumericalError after 50 restarts
// (Mindlin's sphere, ν = 0.3, n = 243: converges up to Q/μP = 0.947).
//
// Convergence is measured by the cost (A.14), see FrictionalResult::error.
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "wearscale/bem/friction_law.hpp"
#include "wearscale/bem/half_space.hpp"
#include "wearscale/bem/traction_operator.hpp"

namespace wearscale::bem {

/// Imposed mean tractions ⟨p_N⟩ ≥ 0 and ⟨p_T⟩ = (x, y) over the cell [Pa].
struct MeanTraction {
  double normal = 0.0;
  double x = 0.0, y = 0.0;
};

/// How the lagged friction bound moves from one subproblem to the next.
///  None:     the law's bound of the last solution, p_T,max = law(p_N) (the
///            plain fixed point; the default);
///  Anderson: Anderson's mixing (type II) of the last `anderson_memory` plain
///            updates (Walker & Ni 2011), kept only while the bound's change
///            shrinks and the mixed bound stays ≥ 0 on the contact; else the
///            plain one. It does not save iterations (docs/bem.md, "Frictional
///            contact"): the iterations go to the inner solves, not to the
///            number of bound updates.
/// Both stop on the same test (the law's bound of the solution changes by less
/// than the tolerance), so where the bound has a fixed point (Coulomb) they
/// reach the same answer; a Tresca bound that cycles is kept where each path
/// leaves it.
enum class OuterAcceleration { None, Anderson };

struct FrictionalOptions {
  static constexpr double max_tolerance = 1e-3;  ///< as ContactOptions::max_tolerance
  static constexpr int max_anderson_memory = 8;
  double tolerance = 1e-10;   ///< on FrictionalResult::error, in (0, max_tolerance]
  int max_iterations = 20000;
  OuterAcceleration outer_acceleration = OuterAcceleration::None;
  int anderson_memory = 4;    ///< past updates mixed, in [1, max_anderson_memory]
  /// Asked once an iteration (if set): true ends the solve with Interrupted,
  /// on every process at the same iteration (as ContactOptions::stop).
  std::function<bool()> stop = nullptr;
};

/// What a surface point does at the solution (the stick/slip map).
enum class ContactState : std::uint8_t { Open = 0, Stick = 1, Slip = 2 };

struct FrictionalResult {
  int iterations = 0;
  int bound_updates = 0;      ///< subproblems solved before the bound held (see above)
  int accelerated_updates = 0;  ///< of those, the ones that took Anderson's mixed bound (OuterAcceleration)
  long unsettled_points = 0;  ///< contact points whose p_T,max still differs from the law's (see above)
  /// ε = ε_N + ε_T, the cost (A.14) made relative:
  ///   ε_N = Σ p_N |g_N| / (Σ p_N · h_rms),
  ///   ε_T = Σ (p_T,max ‖g_T‖ + p_T·g_T) / (Σ p_T,max · h_rms),
  /// h_rms the RMS of h about its mean (1 for a flat surface). The sliding
  /// term equals (A.14)'s (p_T,max − ‖p_T‖)‖g_T‖ when g_T opposes p_T, and is
  /// also > 0 for a point that slides the wrong way.
  double error = 0.0;
  double normal_error = 0.0, tangential_error = 0.0;
  MeanTraction mean_traction;     ///< reached ⟨p⟩ [Pa]
  double contact_fraction = 0.0;  ///< A/A0
  double stick_fraction = 0.0;    ///< sticking area / A0
  double slip_fraction = 0.0;     ///< sliding area / A0
  bool full_sliding = false;      ///< ‖⟨p_T⟩‖ = ⟨p_T,max⟩: every contact point slides
  double interference = 0.0;      ///< δ = max h − d [m], as NormalContact
  /// δ_T, the rigid tangential displacement of the stick zone [m] (NaN in full sliding).
  double tangential_displacement_x = 0.0, tangential_displacement_y = 0.0;
  double elastic_energy = 0.0;    ///< ½∫p·u dA per cell [J]  (4.1)
  double frictional_force_ratio = 0.0;  ///< ‖⟨p_T⟩‖/⟨p_N⟩
};

class FrictionalContact {
 public:
  /// `surface` heights on a periodic grid; E and ν of the elastic flat (the
  /// rigid surface's own compliance folded in beforehand, (A.1)).
  FrictionalContact(const RealField& surface, double young, double poisson, FrictionLaw law);
  /// The same solver on any body (E and ν its own): `surface` holds the
  /// heights of the rows the body holds here (body->local_grid()), and so do
  /// the fields below; every pass reduces its sums through body->sum, so with
  /// a SlabHalfSpace every rank of the job, constructing it with its slab and
  /// making the same calls, takes the same steps and stops at the same
  /// iteration. A solve's result is the whole grid's on every rank.
  FrictionalContact(std::unique_ptr<TractionOperator> body, const RealField& surface, FrictionLaw law);

  /// Solves for the imposed mean tractions. InputError if ⟨p_N⟩ < 0 or if the
  /// tangential load exceeds what friction can carry (‖⟨p_T⟩‖ > μ⟨p_N⟩ for
  /// Coulomb, > σ_m,T A/A0 for Tresca): that is gross sliding, reported and
  /// never clamped. NumericalError on NaN, breakdown or no convergence.
  /// The last solution is the warm start of the next solve.
  FrictionalResult solve(const MeanTraction& load, const FrictionalOptions& options = {});
  /// Forgets the warm start.
  void reset();

  /// p_x, p_y and p_z = p_N [Pa].
  const VectorField& traction() const { return p_; }
  /// u = F * p, all components (zero mean) [m]; valid after a solve.
  const VectorField& displacement() const { return u_; }
  /// g_N (0 in the contact, ≥ 0 outside) [m].
  const RealField& normal_gap() const { return gap_; }
  /// g_T: 0 where sticking, opposed to p_T where sliding (x, y; z unused) [m].
  const VectorField& slip() const { return slip_; }
  /// ContactState per point as 0 (open), 1 (stick), 2 (slip).
  const RealField& stick_slip_map() const { return map_; }

  const RealField& surface() const { return h_; }
  /// The whole grid of the contact; the fields above are on local_grid(), the rows held here.
  const Grid2D& grid() const { return body_->grid(); }
  const Grid2D& local_grid() const { return h_.grid(); }
  const FrictionLaw& law() const { return law_; }
  double young() const { return young_; }
  double poisson() const { return poisson_; }
  /// The last iterations' errors ε (for reports of slow convergence).
  const std::vector<double>& history() const { return history_; }

 private:
  // The phases of one iteration of Algorithm 1 (see the .cpp) and what they pass on.
  struct Iterate {  // carried from one iteration to the next
    double rn_old = 0.0, rt_old = 0.0;  // Σ d² of the normal and tangential gradients
    bool conjugate_n = false, conjugate_t = false;  // false restarts that block's steepest descent
    double bound_change = 1.0, best_change = std::numeric_limits<double>::infinity();  // relative change of the friction bound
    int restarts = 0, stalled = 0;  // tangential restarts; bound updates without progress
    bool settled = false;           // the bound is kept (see the header)
    double last_change = std::numeric_limits<double>::infinity();  // the bound's change at the last update
    double first_error = 0.0;
  };
  struct GapShifts {           // pass 1: the rigid-body shifts of the gaps
    double contact_points = 0.0;  // |contact|
    double pressure_sum = 0.0;    // Σ p_N
    double normal = 0.0;          // mean normal gap on the contact
    double x = 0.0, y = 0.0;      // δ_T: mean displacement of the stick zone (or of the contact)
    bool stick_zone_lost = false; // every point on the cone below the friction capacity
  };
  struct Residual {            // pass 2: the projected gradient and the cost (A.14)
    double error = 0.0, error_n = 0.0, error_t = 0.0;
    double rn = 0.0, rt = 0.0;    // Σ d_N², Σ ‖d_T‖²
    bool penetrates = false;      // some open point has g_N < 0
  };
  struct Slopes {              // the search directions' Σ ∂J/∂p·t and the cone's curvature
    double normal = 0.0, tangential = 0.0, turn_curvature = 0.0;
  };
  enum class Subproblem { Open, Updated, Solved };

  void check_load(const MeanTraction& load) const;
  void warm_start(const MeanTraction& load);
  GapShifts measure_shifts(int iteration, bool stop) const;
  void restart_tangential(const MeanTraction& load, int iteration, Iterate& state);
  Residual gradient(const GapShifts& shifts);
  Subproblem check_subproblem(const Residual& residual, const MeanTraction& load, int iteration, Iterate& state);
  Slopes search_directions(const GapShifts& shifts, Iterate& state, const Residual& residual);
  double normal_direction(double beta, double contact_points);
  double tangential_direction(double beta, const GapShifts& shifts, double& turn_curvature);
  std::pair<double, double> step_lengths(const Slopes& slopes, int iteration);
  void descend(double tau_n, double tau_t, const MeanTraction& load, int iteration, Iterate& state);
  // Brings p_T into the discs ‖p_T‖ ≤ p_T,max(p_N) with the imposed mean,
  // shifting only the points off the cone if `free_only` (and they can carry
  // it); returns false if the discs cannot carry it (gross sliding).
  bool project_tangential(double target_x, double target_y, int iteration, bool free_only);
  // The bound of the next subproblem from the law's bound `next` of this
  // solution: `next` itself, or Anderson's mix; true if mixed.
  bool accelerate_bound(std::vector<double>& next, double change, Iterate& state);
  FrictionalResult finish(int iterations, double error, double error_n, double error_t, const MeanTraction& load);
  // Partial sums of this process → the totals over every point (body_->sum; serial: unchanged).
  template <class... T>
  void sum(T&... values) const {
    body_->sum_each(values...);
  }
  double points() const { return static_cast<double>(body_->grid().size()); }

  RealField h_;
  double young_, poisson_;
  FrictionLaw law_;
  VectorField p_, u_, t_, t_old_, d_, slip_;
  RealField gap_, map_;
  RealField bound_;                  // p_T,max of the current subproblem at points in contact
  std::vector<std::uint8_t> state_;  // per point: open, stick, slip (on the cone), released
  std::unique_ptr<TractionOperator> body_;  // the Green tensor (A.4), all blocks (whole grid or a slab)
  double h_rms_ = 1.0, h_max_ = 0.0;
  double shift_n_ = 0.0, shift_x_ = 0.0, shift_y_ = 0.0;  // gap shifts of the last iteration
  bool all_sliding_ = false, overloaded_ = false;
  double capacity_ = 0.0;  // ⟨p_T,max⟩ at the last projection
  int bound_updates_ = 0, accelerated_updates_ = 0;
  OuterAcceleration acceleration_ = OuterAcceleration::None;
  int memory_ = 4;
  // Anderson's history, oldest first: the plain updates G(b_j) = law(p_N) and
  // their residuals G(b_j) − b_j on this process's points.
  std::vector<std::vector<double>> plain_history_, residual_history_;
  double tolerance_ = 1e-10;  // of the solve under way
  std::vector<double> history_;
};

}  // namespace wearscale::bem
