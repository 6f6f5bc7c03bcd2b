#include "wearscale/bem/normal_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/bem/roughness.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/core/roots.hpp"

namespace wearscale::bem {

namespace {
constexpr const char* kSolver = "bem/normal-contact (Polonsky–Keer)";
constexpr std::size_t kHistory = 12;

double valid_modulus(double e_star) {
  if (!(e_star > 0.0) || !std::isfinite(e_star))
    throw InputError(fmt::format("normal contact: E* = {} is not allowed; allowed: E* > 0", e_star));
  return e_star;
}

std::unique_ptr<NormalOperator> serial_body(const Grid2D& g, double e_star, Boundary boundary) {
  valid_modulus(e_star);
  if (g.nx < 2 || g.ny < 2) throw InputError("normal contact: the grid needs at least 2×2 points");
  return std::make_unique<HalfSpaceNormal>(g, e_star, boundary);
}
}  // namespace

// A grid whose solver fits the memory limit, checked before anything of it is allocated: 160 B per point (the
// contact study's estimate, measured at 1024²), for every caller (the CLI checks it first, naming its key).
static const Grid2D& within_memory(const Grid2D& g) {
  require_memory(160.0 * static_cast<double>(g.size()), fmt::format("a normal contact of {} × {} points", g.nx, g.ny),
                 "use a smaller grid");
  return g;
}

NormalContact::NormalContact(const RealField& surface, double e_star, Boundary boundary)
    : NormalContact(serial_body(within_memory(surface.grid()), e_star, boundary), surface, e_star) {
  serial_ = &static_cast<const HalfSpaceNormal&>(*body_).half_space();
}

NormalContact::NormalContact(std::unique_ptr<NormalOperator> body, const RealField& surface, double e_star)
    : body_(std::move(body)), h_(surface), p_(surface.grid()), u_(surface.grid()), t_(surface.grid()),
      gap_(surface.grid()), e_star_(valid_modulus(e_star)) {
  if (!(surface.grid() == body_->local_grid()))
    throw std::invalid_argument("NormalContact: the surface is not on the rows the body holds");
  set_surface(surface);
}

const HalfSpace& NormalContact::half_space() const {
  if (serial_ == nullptr) throw std::logic_error("NormalContact::half_space: not a serial body");
  return *serial_;
}

void NormalContact::set_surface(const RealField& surface) {
  if (!(surface.grid() == h_.grid())) throw std::invalid_argument("NormalContact::set_surface: grid changed");
  h_ = surface;
  ramp_.clear();  // the kept solutions were for another surface
  const SurfaceScale scale = surface_scale(*body_, h_, "normal contact");
  h_rms_ = scale.h_rms;
  h_max_ = scale.h_max;
}

void NormalContact::reset() {
  p_.fill(0.0);
  ramp_.clear();
}

void NormalContact::set_warm_start(std::span<const double> pressure, double gap_shift) {
  if (pressure.size() != p_.size())
    throw InputError(fmt::format("normal contact: a warm start of {} pressures for a grid of {} points",
                                 pressure.size(), p_.size()));
  for (double v : pressure)
    if (!std::isfinite(v) || v < 0.0) throw InputError("normal contact: a warm-start pressure is negative, NaN or infinite");
  if (!std::isfinite(gap_shift)) throw InputError("normal contact: the warm-start mean gap is not finite");
  std::copy(pressure.begin(), pressure.end(), p_.begin());
  gap_shift_ = gap_shift;
  ramp_.clear();
}

// Pass 1 over the contact S = {p > 0}: mean gap ḡ, Σ_S (g − ḡ)² (by sums
// shifted by the last ḡ, which keeps them free of cancellation), and the mean
// of the previous direction on the new S.
NormalContact::ContactGap NormalContact::measure_gap(int iteration, bool stop) const {
  const std::size_t n = h_.size();
  const double *p = p_.data(), *u = u_.data(), *t = t_.data(), *h = h_.data();
  const double shift = gap_shift_;
  double n_s = 0.0, sum1 = 0.0, sum2 = 0.0, t_old_sum = 0.0;
#pragma omp parallel for simd reduction(+ : n_s, sum1, sum2, t_old_sum) schedule(static)
  for (std::size_t k = 0; k < n; ++k) {
    const double in = p[k] > 0.0 ? 1.0 : 0.0;
    const double d = (u[k] - h[k] - shift) * in;
    n_s += in;
    sum1 += d;
    sum2 += d * d;
    t_old_sum += t[k] * in;
  }
  double stops = stop ? 1.0 : 0.0;  // any process asked: every one stops here
  sum(n_s, sum1, sum2, t_old_sum, stops);
  if (stops > 0.0) throw Interrupted(fmt::format("{}: stopped at iteration {} (a stop was requested)", kSolver, iteration));
  if (n_s == 0.0) throw NumericalError(kSolver, iteration, "contact area", "the contact vanished (no point with p > 0)");
  ContactGap gap;
  gap.points = n_s;
  gap.mean = shift + sum1 / n_s;
  gap.norm2 = sum2 - sum1 * sum1 / n_s;
  gap.direction_mean = t_old_sum / n_s;
  if (!(gap.norm2 > 64.0 * std::numeric_limits<double>::epsilon() * sum2)) {
    // The shift was far from the mean: the sums cancelled. Recompute exactly.
    const double g_mean = gap.mean;
    double g_norm = 0.0;
#pragma omp parallel for simd reduction(+ : g_norm) schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
      const double d = p[k] > 0.0 ? u[k] - h[k] - g_mean : 0.0;
      g_norm += d * d;
    }
    sum(g_norm);
    gap.norm2 = g_norm;
  }
  return gap;
}

// Pass 2: error; conjugate direction t = g + β (t_old − ⟨t_old⟩_S) on S, 0
// elsewhere. Projecting the direction to zero mean on S keeps the load
// constant along it, so the step needs only t·Kt (no mean of K t on S).
NormalContact::Descent NormalContact::search_direction(const ContactGap& gap, double beta) {
  const std::size_t n = h_.size();
  const double *p = p_.data(), *u = u_.data(), *h = h_.data();
  double* t = t_.data();
  const double g_mean = gap.mean, t_old_mean = gap.direction_mean;
  double err_num = 0.0, p_sum = 0.0, gt = 0.0, penetrating = 0.0;
#pragma omp parallel for simd reduction(+ : err_num, p_sum, gt, penetrating) schedule(static)
  for (std::size_t k = 0; k < n; ++k) {
    const double g = u[k] - h[k] - g_mean;
    const bool in = p[k] > 0.0;
    const double tk = in ? g + beta * (t[k] - t_old_mean) : 0.0;
    t[k] = tk;
    err_num += in ? p[k] * std::abs(g) : 0.0;
    p_sum += p[k];
    gt += g * tk;
    penetrating += (!in && g < 0.0) ? 1.0 : 0.0;
  }
  sum(err_num, p_sum, gt, penetrating);
  return {err_num / (p_sum * h_rms_), gt, penetrating > 0.0};
}

// Pass 2 (preconditioned): the residual r = g − ḡ on S, the error and penetration.
NormalContact::Descent NormalContact::residual(const ContactGap& gap) {
  const std::size_t n = h_.size();
  const double *p = p_.data(), *u = u_.data(), *h = h_.data();
  double* r = gap_.data();  // scratch until finish() writes the gap
  const double g_mean = gap.mean;
  double err_num = 0.0, p_sum = 0.0, penetrating = 0.0;
#pragma omp parallel for simd reduction(+ : err_num, p_sum, penetrating) schedule(static)
  for (std::size_t k = 0; k < n; ++k) {
    const double g = u[k] - h[k] - g_mean;
    const bool in = p[k] > 0.0;
    r[k] = in ? g : 0.0;
    err_num += in ? p[k] * std::abs(g) : 0.0;
    p_sum += p[k];
    penetrating += (!in && g < 0.0) ? 1.0 : 0.0;
  }
  sum(err_num, p_sum, penetrating);
  return {err_num / (p_sum * h_rms_), 0.0, penetrating > 0.0};
}

// Pass 3 (preconditioned): t = (z − z̄) + β (t_old − ⟨t_old⟩_S) on S, 0 elsewhere,
// z̄ the mean of z = S r on S (the load stays constant along t), β = Σ r z / (Σ r z)_old
// (Fletcher–Reeves in the preconditioned inner product).
void NormalContact::preconditioned_direction(const ContactGap& gap, Iterate& state, Descent& d) {
  const std::size_t n = h_.size();
  const double *p = p_.data(), *r = gap_.data(), *z = z_.data();
  double* t = t_.data();
  double z_sum = 0.0, rz = 0.0, r_sum = 0.0;
#pragma omp parallel for simd reduction(+ : z_sum, rz, r_sum) schedule(static)
  for (std::size_t k = 0; k < n; ++k) {
    const bool in = p[k] > 0.0;
    z_sum += in ? z[k] : 0.0;
    rz += r[k] * z[k];  // r = 0 off S
    r_sum += r[k];
  }
  sum(z_sum, rz, r_sum);
  const double z_mean = z_sum / gap.points;
  rz -= z_mean * r_sum;  // Σ_S r (z − z̄)
  const double beta = state.conjugate && state.residual_old > 0.0 ? rz / state.residual_old : 0.0;
  state.residual_old = rz;
  const double t_old_mean = gap.direction_mean;
  double slope = 0.0;
#pragma omp parallel for simd reduction(+ : slope) schedule(static)
  for (std::size_t k = 0; k < n; ++k) {
    const double tk = p[k] > 0.0 ? (z[k] - z_mean) + beta * (t[k] - t_old_mean) : 0.0;
    t[k] = tk;
    slope += r[k] * tk;
  }
  sum(slope);
  d.slope = slope;
}

// Step length τ = Σ g t / Σ t (K t) (+ t A t with an added compliance), the denominator by Parseval from the
// spectrum of t: one forward FFT instead of a full convolution.
double NormalContact::step_length(const Descent& d, int iteration) {
  const double tkt = body_->form(t_) + (added_ != nullptr ? added_->quadratic_form(t_) : 0.0);
  // No descent direction (a contact of one point, or a flat gap on S) while
  // points outside still penetrate: admit them with a cell's own stiffness.
  const double tau =
      (tkt == 0.0 && d.slope == 0.0) ? 1.0 / (readmit_stiffness_ * body_->self_compliance()) : d.slope / tkt;
  if (!std::isfinite(tau) || !(tkt > 0.0 || d.slope == 0.0))
    throw NumericalError(kSolver, iteration, "step length", fmt::format("τ = {} (t·Kt = {})", tau, tkt));
  return tau;
}

// Pass 3: descend, project on p ≥ 0, re-admit penetrating points, sum for the mean.
void NormalContact::descend(double tau, double g_mean, double p0, int iteration, Iterate& state) {
  const std::size_t n = h_.size();
  double* p = p_.data();
  const double *u = u_.data(), *t = t_.data(), *h = h_.data();
  // The re-admission stiffness: per point (readmit_field_) or one value (stride 0).
  const double* stiffness = readmit_field_.empty() ? &readmit_stiffness_ : readmit_field_.data();
  const std::size_t stride = readmit_field_.empty() ? 0 : 1;
  const double alpha = state.alpha;
  double overlap = 0.0, new_sum = 0.0;
#pragma omp parallel for simd reduction(+ : overlap, new_sum) schedule(static)
  for (std::size_t k = 0; k < n; ++k) {
    const double descended = p[k] > 0.0 ? std::max(alpha * p[k] - tau * t[k], 0.0) : 0.0;
    const double g = u[k] - h[k] - g_mean;
    const bool readmit = descended == 0.0 && g < 0.0;
    const double pk = readmit ? -tau * stiffness[k * stride] * g : descended;
    overlap += readmit ? 1.0 : 0.0;
    p[k] = pk;
    new_sum += pk;
  }
  sum(overlap, new_sum);
  state.conjugate = overlap == 0.0;
  if (!(new_sum > 0.0)) throw NumericalError(kSolver, iteration, "pressure", "all pressures vanished");
  state.alpha = p0 * points() / new_sum;  // impose ⟨p⟩ = p0 (A.6c)
}

// The load predictor (a secant in the load): λ(p0) ≈ λ₂ + w (λ₂ − λ₁),
// w = (p0 − P₂)/(P₂ − P₁), p = max(λ, 0), with λ = p − c g of the kept
// solutions (keep_solution). On a fixed contact set the solution is affine in
// the load, so the secant is exact there; a point about to enter the contact
// has a closing gap, so λ extrapolates it to a small pressure where the plain
// secant of p would leave it at 0 for the iteration to re-admit. The mean gap
// on the contact is extrapolated alike.
bool NormalContact::predict(double p0) {
  if (ramp_.size() < 2) return false;
  const Solution &a = ramp_[0], &b = ramp_[1];
  const double w = (p0 - b.load) / (b.load - a.load);  // loads distinct (keep_solution)
  if (w == 0.0 || !(std::abs(w) <= 4.0)) return false;  // far from the ramp: the plain warm start
  const std::size_t n = p_.size();
  const double *la = a.lambda.data(), *lb = b.lambda.data();
  double* p = p_.data();
#pragma omp parallel for simd schedule(static)
  for (std::size_t k = 0; k < n; ++k) p[k] = std::max(lb[k] + w * (lb[k] - la[k]), 0.0);
  gap_shift_ = b.gap_shift + w * (b.gap_shift - a.gap_shift);
  return true;
}

// Keeps λ = p − c g of a converged solve (p on the contact, −c g ≤ 0 outside,
// so p = max(λ, 0)), c = S(0)/10: a tenth of a cell's own stiffness under the
// preconditioner. On the rough case at 512², +0.1 % load steps, c = 0, 0.01,
// 0.03, 0.1, 0.3, 1 × S(0) gave 12, 11, 11, 11, 11, 12 iterations a step;
// +1 %: 17 (c = 0), 16 (0.03), 15 (0.1).
void NormalContact::keep_solution(double p0, double gap_mean) {
  if (!ramp_.empty() && ramp_.back().load == p0) ramp_.pop_back();  // the same load again: keep the newer
  if (ramp_.size() == 2) ramp_.erase(ramp_.begin());
  const double c = 0.1 * body_->stiffness_diagonal();
  std::vector<double> lambda(p_.size());
  for (std::size_t k = 0; k < lambda.size(); ++k) lambda[k] = p_[k] - c * gap_[k];
  ramp_.push_back({p0, gap_mean, std::move(lambda)});
}

ContactResult NormalContact::solve_mean_pressure(double p0, const ContactOptions& opt) {
  const ContactResult r = solve(p0, opt);
  check_window();
  return r;
}

void NormalContact::check_window() const {
  if (body_->boundary() != Boundary::Free) return;
  // The rows held here (all of them on one process, a slab under MPI): the
  // first and last columns everywhere, the first and last rows where held.
  const Grid2D& g = grid();
  const std::size_t rows = p_.grid().nx, ny = g.ny, first = body_->first_row();
  bool edge = false;
  for (std::size_t i = 0; i < rows && !edge; ++i) edge = p_(i, 0) > 0.0 || p_(i, ny - 1) > 0.0;
  for (const std::size_t i : {std::size_t{0}, g.nx - 1})
    if (i >= first && i < first + rows)
      for (std::size_t j = 0; j < ny && !edge; ++j) edge = p_(i - first, j) > 0.0;
  if (body_->max(edge ? 1.0 : 0.0) > 0.0)
    throw InputError(fmt::format(
        "normal contact: with a free boundary the contact reaches the edge of the {:g} m × {:g} m window, so the "
        "body beyond it is missing and the solution would be wrong; allowed: a contact inside the window (a larger "
        "size, or a smaller load)",
        g.lx, g.ly));
}

ContactResult NormalContact::solve(double p0, const ContactOptions& opt) {
  if (!(p0 >= 0.0) || !std::isfinite(p0))
    throw InputError(fmt::format("normal contact: mean pressure {} is not allowed; allowed: ≥ 0", p0));
  if (!(opt.tolerance > 0.0 && opt.tolerance <= ContactOptions::max_tolerance))
    throw InputError(fmt::format("normal contact: tolerance = {:g}; allowed: (0, {:g}] (a larger one lets a solve "
                                 "stop before it has an answer)",
                                 opt.tolerance, ContactOptions::max_tolerance));
  history_.clear();
  if (p0 == 0.0) {
    ramp_.clear();
    p_.fill(0.0);
    u_.fill(0.0);
    return finish(0, 0.0, -h_max_);  // the summit just touches: δ = 0
  }
  // Warm start: the load ramp's prediction or the previous pressure, rescaled to p0; else uniform p0.
  if (opt.predict_load) predict(p0);
  Iterate state;
  double mean = 0.0;
  for (double v : p_) mean += v;
  sum(mean);
  mean /= points();
  if (mean > 0.0 && std::isfinite(mean))
    state.alpha = p0 / mean;
  else
    p_.fill(p0);
  t_.fill(0.0);

  const bool preconditioned = opt.method != ContactMethod::PolonskyKeer;
  const bool two_level = opt.method == ContactMethod::TwoLevelCG;
  if (preconditioned && !(z_.grid() == h_.grid())) z_ = RealField(h_.grid());
  // The added compliance's own preconditioner of K + A, when it has one.
  const bool own = preconditioned && added_ != nullptr && added_->has_preconditioner();
  readmit_stiffness_ = preconditioned ? body_->stiffness_diagonal() : 1.0;
  readmit_field_ = own ? added_->precondition_diagonal() : std::span<const double>();
  if (!readmit_field_.empty() && readmit_field_.size() != p_.size())
    throw std::logic_error("NormalContact: the added compliance's preconditioner diagonal is not one value a point");
  double first_error = 0.0;
  for (int it = 0; it < opt.max_iterations; ++it) {
    body_->displacement(p_, u_, state.alpha);  // u = K (α p)
    if (added_ != nullptr) added_->add(p_, state.alpha, u_);  // + A (α p)
    const ContactGap gap = measure_gap(it, opt.stop && opt.stop());
    gap_shift_ = gap.mean;  // the last mean gap: carried across solves (warm start)
    Descent descent;
    if (preconditioned) {
      descent = residual(gap);
    } else {
      const double beta = state.conjugate && state.residual_old > 0.0 ? gap.norm2 / state.residual_old : 0.0;
      descent = search_direction(gap, beta);
    }
    if (!std::isfinite(descent.error))
      throw NumericalError(kSolver, it, "orthogonality error", "not finite (NaN in u or p)");
    if (it == 0) first_error = descent.error;
    if (it % 10 == 0) log::debug("{}: iteration {}, ε = {:.3g}", kSolver, it, descent.error);  // long solves: -v
    history_.push_back(descent.error);
    if (history_.size() > kHistory) history_.erase(history_.begin());
    if (descent.error < opt.tolerance && !descent.penetrates) {
      for (double& v : p_) v *= state.alpha;
      const ContactResult r = finish(it, descent.error, gap.mean);
      if (opt.predict_load) keep_solution(p0, gap.mean);
      return r;
    }
    if (preconditioned) {
      if (own)
        added_->precondition(gap_, z_);  // z = M r ≈ (K + A)⁻¹ r
      else if (two_level)
        body_->two_level_stiffness(gap_, z_);  // z = M r ≈ S r
      else
        body_->stiffness(gap_, z_);  // z = S r
      preconditioned_direction(gap, state, descent);
    } else {
      state.residual_old = gap.norm2;
    }
    descend(step_length(descent, it), gap.mean, p0, it, state);
  }
  throw NumericalError(kSolver, opt.max_iterations, "orthogonality error",
                       fmt::format("no convergence to {:g} in {} iterations (ε = {:.3g} at the first iteration); "
                                   "last {} errors: {:.3g}",
                                   opt.tolerance, opt.max_iterations, first_error, history_.size(),
                                   fmt::join(history_, ", ")));
}

ContactResult NormalContact::finish(int iterations, double error, double g_mean) {
  const std::size_t n = h_.size();
  double p_sum = 0.0, contact = 0.0, work = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    gap_[k] = p_[k] > 0.0 ? 0.0 : u_[k] - h_[k] - g_mean;  // ≥ 0 to the solver's tolerance
    p_sum += p_[k];
    contact += p_[k] > 0.0 ? 1.0 : 0.0;
    work += p_[k] * u_[k];
  }
  sum(p_sum, contact, work);
  ContactResult r;
  r.iterations = iterations;
  r.error = error;
  r.mean_pressure = p_sum / points();
  r.contact_fraction = contact / points();
  r.interference = h_max_ + g_mean;
  r.elastic_energy = 0.5 * work * grid().cell_area();
  return r;
}

ContactResult NormalContact::solve_interference(double delta, const ContactOptions& opt) {
  if (!std::isfinite(delta)) throw InputError("normal contact: the interference must be finite");
  if (delta <= 0.0) return solve_mean_pressure(0.0, opt);
  // Bracket: δ(p0) grows with p0 and δ → 0⁺ as p0 → 0 for a surface with one summit.
  const double scale = e_star_ * std::max(delta, 1e-300) / std::max(grid().lx, grid().ly);
  double lo = 0.0, hi = scale;
  for (int k = 0; solve(hi, opt).interference < delta; ++k) {
    lo = hi;
    hi *= 4.0;
    if (k > 200) throw NumericalError(kSolver, k, "interference", "cannot bracket the imposed interference");
  }
  const double p0 = find_root([&](double p) { return solve(p, opt).interference - delta; }, lo, hi,
                              1e-12 * hi, kSolver);
  const ContactResult r = solve(p0, opt);
  check_window();
  return r;
}

}  // namespace wearscale::bem
