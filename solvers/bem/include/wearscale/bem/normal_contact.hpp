#pragma once
// Frictionless normal contact of a rigid surface on a periodic elastic flat
// (§2.3.2): minimise ½∫p u − ∫p h under the Hertz–Signorini–Moreau conditions
// p ≥ 0, g ≥ 0, p g = 0 (2.43) with the constrained conjugate gradient of
// Polonsky & Keer (1999), preconditioned by default: the gradient (the gap
// on the contact) is mapped to a pressure by S = E*|q|/2, the inverse of the
// half-space's normal block, before it enters the conjugate directions
// (Vollebregt, J. Comput. Phys. 2014). Unpreconditioned, the iterations grow
// with the resolution (the spectrum of the operator on the contact spreads as
// 1/q); preconditioned they grow only logarithmically, at the price of one
// FFT pair more per iteration (see docs/bem.md for the measured table).
//
// Heights h are positive towards the elastic body; u > 0 moves its surface
// away (into the solid). The gap is g = u − h + d, d the rigid-body level.
//
// Convergence: the relative orthogonality error
//     ε = Σ_x p(x) |g(x)|  /  ( Σ_x p(x) · h_rms ),
// with g shifted so that its mean over the contact is zero and h_rms the RMS
// of h about its mean (1 for a flat surface), must fall below `tolerance`
// while no point outside the contact penetrates (g < 0 where p = 0).
#include <functional>
#include <memory>
#include <span>
#include <stdexcept>
#include <vector>

#include "wearscale/bem/half_space.hpp"
#include "wearscale/bem/normal_operator.hpp"

namespace wearscale::bem {

/// A linear compliance added to the half-space's, symmetric and positive
/// semi-definite: the surface then moves by u = K p + A p. An implicit wear
/// step is one (wearing in proportion to the pressure over a step lowers a
/// surface as a compliance would); A = 0 is the plain contact. Every method
/// takes it. The preconditioned ones use the compliance's own preconditioner
/// of K + A when it has one (precondition()), else the half-space's S (still
/// SPD, so the conjugate directions still converge, more slowly the more A
/// dominates K).
class AddedCompliance {
 public:
  virtual ~AddedCompliance() = default;
  /// u += scale · A p
  virtual void add(const RealField& p, double scale, RealField& u) const = 0;
  /// t · A t
  virtual double quadratic_form(const RealField& t) const = 0;
  /// Whether it has a preconditioner M of K + A (false, the default: the solver uses the half-space's S).
  virtual bool has_preconditioner() const { return false; }
  /// z = M r, M a symmetric positive definite approximation of (K + A)⁻¹, allocating nothing.
  virtual void precondition(const RealField& /*r*/, RealField& /*z*/) const {
    throw std::logic_error("AddedCompliance::precondition: this compliance has no preconditioner");
  }
  /// M at offset 0, per point of the grid [Pa/m]: the pressure per unit gap
  /// a penetrating point is re-admitted with (as S(0) is for S; a compliance
  /// that differs from point to point needs it per point, or the contact set
  /// overshoots where A is large).
  virtual std::span<const double> precondition_diagonal() const { return {}; }
};

enum class ContactMethod {
  PreconditionedCG,  ///< Polonsky–Keer with the FFT preconditioner S
  PolonskyKeer,      ///< the textbook, unpreconditioned Polonsky–Keer iteration
  TwoLevelCG,        ///< preconditioned by TwoLevelStiffness (S where the body has no coarse grid): the default
};

struct ContactOptions {
  /// The largest tolerance a solve accepts: above it a solve may stop with the
  /// contact still penetrating or a pressure nowhere near the answer (0.999999
  /// ended at iteration 0 with full contact).
  static constexpr double max_tolerance = 1e-3;
  double tolerance = 1e-12;   ///< on ε above, in (0, max_tolerance]
  int max_iterations = 10000;
  ContactMethod method = ContactMethod::TwoLevelCG;
  /// Asked once an iteration (if set): true ends the solve with Interrupted,
  /// on every process at the same iteration (the answers are summed with the
  /// iteration's own sums), e.g. [] { return interrupt_requested(); }.
  std::function<bool()> stop = nullptr;
  /// Load ramps (a wear map walking the loads on one surface): start from the
  /// secant through the last two solutions on this surface, extrapolated to
  /// this load, instead of the last one rescaled (see kept_solutions()).
  bool predict_load = false;
};

struct ContactResult {
  int iterations = 0;
  double error = 0.0;             ///< ε at the solution
  double mean_pressure = 0.0;     ///< ⟨p⟩ [Pa]
  double contact_fraction = 0.0;  ///< A/A0: share of points with p > 0
  double interference = 0.0;      ///< δ = max h − d: summit depth below the mean deformed surface [m]
  double elastic_energy = 0.0;    ///< ½∫p u dA per cell [J]
};

class NormalContact {
 public:
  /// `surface` heights on the grid; `e_star` the contact modulus (1.12).
  /// Periodic: the grid is one cell of a periodic surface. Free: it is a window
  /// on an isolated body (a sphere, a pin, an asperity) and u the true
  /// displacement, so `interference` is the approach of the rigid body towards
  /// the far field (Hertz's δ) with no image correction; a solution whose
  /// pressure reaches the outermost ring of cells is refused (InputError: the
  /// window is too small for the contact).
  NormalContact(const RealField& surface, double e_star, Boundary boundary = Boundary::Periodic);
  /// The same solver on any body: `surface` holds the heights of the rows the
  /// body holds here (body->local_grid()), and so do pressure(), gap() and
  /// displacement(); sums go through body->sum. With a SlabHalfSpace every
  /// rank of the job constructs it with its slab and calls the same solves.
  NormalContact(std::unique_ptr<NormalOperator> body, const RealField& surface, double e_star);
  /// The elastic body of the serial solver, its normal block only (HalfSpace::normal);
  /// std::logic_error for another body.
  const HalfSpace& half_space() const;
  const NormalOperator& body() const { return *body_; }

  /// Replaces the rigid surface, keeping the last pressure as a warm start.
  void set_surface(const RealField& surface);
  /// Forgets the warm start.
  void reset();
  /// Adds `compliance` to the half-space's in the next solves (nullptr: none).
  /// It must outlive those solves; displacement() and the elastic energy then
  /// include its share.
  void set_added_compliance(const AddedCompliance* compliance) {
    if (compliance != added_) ramp_.clear();
    added_ = compliance;
  }
  /// The warm start carried from one solve to the next: the last pressure
  /// (pressure()) and the mean gap on the contact. Restoring both (from a
  /// checkpoint) makes the next solve bit-identical to the one an
  /// uninterrupted computation would do.
  double warm_gap_shift() const { return gap_shift_; }
  void set_warm_start(std::span<const double> pressure, double gap_shift);
  /// Solutions kept for ContactOptions::predict_load on this surface (0, 1 or
  /// 2, at distinct loads; a secant needs 2). set_surface, reset,
  /// set_warm_start and a change of the added compliance forget them.
  std::size_t kept_solutions() const { return ramp_.size(); }

  /// Solves for the imposed mean pressure p0 ≥ 0 (InputError if negative;
  /// NumericalError on NaN, breakdown or no convergence).
  ContactResult solve_mean_pressure(double p0, const ContactOptions& options = {});
  /// Solves for the imposed interference δ (see ContactResult): an outer
  /// bracketing root search (GSL Brent) on the mean pressure, warm-started.
  ContactResult solve_interference(double delta, const ContactOptions& options = {});

  const RealField& pressure() const { return p_; }
  /// Surface displacement u (zero mean), valid after a solve.
  const RealField& displacement() const { return u_; }
  /// Gap g = u − h + d, zero in the contact and ≥ 0 (to the tolerance) outside; valid after a solve.
  const RealField& gap() const { return gap_; }
  const RealField& surface() const { return h_; }
  /// The whole grid (serial: the fields' grid; distributed: the fields hold rows of it).
  const Grid2D& grid() const { return body_->grid(); }
  double e_star() const { return e_star_; }
  /// The last iterations' errors ε (for reports of slow convergence).
  const std::vector<double>& history() const { return history_; }

 private:
  // The phases of one Polonsky–Keer iteration (see the .cpp) and what they pass on.
  struct ContactGap {          // pass 1: the gap on the contact S = {p > 0}
    double points = 0.0;       // |S|
    double mean = 0.0;         // ḡ, the mean gap on S
    double norm2 = 0.0;        // Σ_S (g − ḡ)²
    double direction_mean = 0.0;  // mean over S of the previous direction
  };
  struct Descent {             // pass 2: the search direction and the error
    double error = 0.0;        // ε (see above)
    double slope = 0.0;        // Σ g t
    bool penetrates = false;   // some point outside S has g < 0
  };
  struct Iterate {             // carried from one iteration to the next
    double alpha = 1.0;        // the pressure is α·p_ (the rescaling to p0 folded into the next pass)
    double residual_old = 0.0; // Σ_S r z of the last iteration (z = r unpreconditioned: Σ_S (g − ḡ)²)
    bool conjugate = false;    // δ of Polonsky–Keer: false restarts steepest descent
  };
  ContactGap measure_gap(int iteration, bool stop) const;
  // Polonsky–Keer: the direction straight from the gap (and the error), in one pass.
  Descent search_direction(const ContactGap& gap, double beta);
  // Preconditioned: the residual r = g − ḡ on S (into gap_) and the error, then,
  // after z = S r (into z_), the direction from z.
  Descent residual(const ContactGap& gap);
  void preconditioned_direction(const ContactGap& gap, Iterate& state, Descent& descent);
  double step_length(const Descent& descent, int iteration);
  // Descends by τ, projects on p ≥ 0, re-admits penetrating points and rescales to p0.
  void descend(double tau, double g_mean, double p0, int iteration, Iterate& state);
  // The warm start of a load ramp: the secant through the kept solutions, extrapolated to p0.
  bool predict(double p0);
  void keep_solution(double p0, double gap_mean);
  ContactResult finish(int iterations, double error, double g_mean);
  ContactResult solve(double p0, const ContactOptions& options);
  // InputError if a free window's contact reaches its border.
  void check_window() const;

  // Sums over every point held by any process, in place (the body's reduction).
  template <class... T>
  void sum(T&... values) const {
    body_->sum_each(values...);
  }
  double points() const { return static_cast<double>(grid().size()); }

  std::unique_ptr<NormalOperator> body_;
  const HalfSpace* serial_ = nullptr;  // the serial body's half-space (half_space())
  RealField h_, p_, u_, t_, gap_, z_;  // z_: the preconditioned residual (empty unless used)
  // The pressure a penetrating point is re-admitted with, per unit gap and step:
  // 1 (Polonsky–Keer) or S at offset 0 (preconditioned) [Pa/m].
  double readmit_stiffness_ = 1.0;
  std::span<const double> readmit_field_;  // per point, when the added compliance's preconditioner gives it
  double e_star_, h_rms_ = 1.0, h_max_ = 0.0;
  double gap_shift_ = 0.0;  // running estimate of the mean gap on the contact
  std::vector<double> history_;
  const AddedCompliance* added_ = nullptr;
  struct Solution {  // a converged solve kept for the load predictor
    double load = 0.0, gap_shift = 0.0;
    std::vector<double> lambda;  // p − c g (see predict)
  };
  std::vector<Solution> ramp_;  // the last two, oldest first
};

}  // namespace wearscale::bem
