#pragma once
// Frictionless normal contact of a rigid surface on a periodic elastic flat
// (§2.3.2): minimise ½∫p u − ∫p h under the Hertz–Signorini–Moreau conditions
// p ≥ 0, g ≥ 0, p g = 0 (2.43) with the constrained conjugate gradient of
// Polonsky & Keer (1999).
//
// Heights h are positive towards the elastic body; u > 0 moves its surface
// away (into the solid). The gap is g = u − h + d, d the rigid-body level.
//
// Convergence: the relative orthogonality error
//     ε = Σ_x p(x) |g(x)|  /  ( Σ_x p(x) · h_rms ),
// with g shifted so that its mean over the contact is zero and h_rms the RMS
// of h about its mean (1 for a flat surface), must fall below `tolerance`
// while no point outside the contact penetrates (g < 0 where p = 0).
#include <span>
#include <vector>

#include "wearscale/core/fft.hpp"

namespace wearscale::bem {

/// A linear compliance added to the half-space's, symmetric and positive
/// semi-definite: the surface then moves by u = K p + A p. An implicit wear
/// step is one (wearing in proportion to the pressure over a step lowers a
/// surface as a compliance would); A = 0 is the plain contact.
class AddedCompliance {
 public:
  virtual ~AddedCompliance() = default;
  /// u += scale · A p
  virtual void add(const RealField& p, double scale, RealField& u) const = 0;
  /// t · A t
  virtual double quadratic_form(const RealField& t) const = 0;
};

struct ContactOptions {
  double tolerance = 1e-12;   ///< on ε above
  int max_iterations = 10000;
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
  /// `surface` heights on a periodic grid; `e_star` the contact modulus (1.12).
  NormalContact(const RealField& surface, double e_star);

  /// Replaces the rigid surface, keeping the last pressure as a warm start.
  void set_surface(const RealField& surface);
  /// Forgets the warm start.
  void reset();
  /// Adds `compliance` to the half-space's in the next solves (nullptr: none).
  /// It must outlive those solves; displacement() and the elastic energy then
  /// include its share.
  void set_added_compliance(const AddedCompliance* compliance) { added_ = compliance; }
  /// The warm start carried from one solve to the next: the last pressure
  /// (pressure()) and the mean gap on the contact. Restoring both (from a
  /// checkpoint) makes the next solve bit-identical to the one an
  /// uninterrupted computation would do.
  double warm_gap_shift() const { return gap_shift_; }
  void set_warm_start(std::span<const double> pressure, double gap_shift);

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
  const Grid2D& grid() const { return h_.grid(); }
  double e_star() const { return e_star_; }
  /// The last iterations' errors ε (for reports of slow convergence).
  const std::vector<double>& history() const { return history_; }

 private:
  void convolve(const RealField& in, RealField& out, double scale);
  double quadratic_form(const RealField& t);  // Σ_x t (K t)
  ContactResult finish(int iterations, double error, double g_mean);

  RealField h_, p_, u_, t_, gap_;
  ComplexField spectrum_;
  std::vector<double> kernel_;  // 2/(E* q)/N on the half spectrum; 0 at q = 0
  std::shared_ptr<const FFTPlan> plan_;
  double e_star_, h_rms_ = 1.0, h_max_ = 0.0;
  double gap_shift_ = 0.0;  // running estimate of the mean gap on the contact
  double self_compliance_ = 1.0;  // u at a cell per unit pressure on that cell [m/Pa]
  std::vector<double> history_;
  const AddedCompliance* added_ = nullptr;
};

}  // namespace wearscale::bem
