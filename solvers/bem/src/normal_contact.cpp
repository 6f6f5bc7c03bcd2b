#include "wearscale/bem/normal_contact.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::bem {

namespace {
constexpr const char* kSolver = "bem/normal-contact (Polonsky–Keer)";
constexpr std::size_t kHistory = 12;
}  // namespace

NormalContact::NormalContact(const RealField& surface, double e_star)
    : h_(surface), p_(surface.grid()), u_(surface.grid()), t_(surface.grid()), r_(surface.grid()),
      gap_(surface.grid()), spectrum_(ComplexField::spectrum_of(surface.grid())), e_star_(e_star) {
  const Grid2D& g = surface.grid();
  if (!(e_star > 0.0) || !std::isfinite(e_star))
    throw InputError(fmt::format("normal contact: E* = {} is not allowed; allowed: E* > 0", e_star));
  if (g.nx < 2 || g.ny < 2) throw InputError("normal contact: the grid needs at least 2×2 points");
  plan_ = FFTPlanCache::global().plan(g);
  kernel_.resize(g.spectral_size());
  const double s = 2.0 / (e_star * static_cast<double>(g.size()));  // (2.39) with E*, 1/N folded in
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.spectral_ny(); ++j) {
      const double qx = g.wavenumber_x(i), qy = g.wavenumber_y(j);
      const double q = std::sqrt(qx * qx + qy * qy);
      kernel_[i * g.spectral_ny() + j] = q > 0.0 ? s / q : 0.0;
    }
  set_surface(surface);
}

void NormalContact::set_surface(const RealField& surface) {
  if (!(surface.grid() == h_.grid())) throw std::invalid_argument("NormalContact::set_surface: grid changed");
  h_ = surface;
  double mean = 0.0, max = -INFINITY;
  for (double v : h_) {
    if (!std::isfinite(v)) throw InputError("normal contact: the surface has a NaN or infinite height");
    mean += v;
    max = std::max(max, v);
  }
  mean /= static_cast<double>(h_.size());
  double var = 0.0;
  for (double v : h_) var += (v - mean) * (v - mean);
  h_rms_ = std::sqrt(var / static_cast<double>(h_.size()));
  if (!(h_rms_ > 0.0)) h_rms_ = 1.0;
  h_max_ = max;
}

void NormalContact::reset() { p_.fill(0.0); }

void NormalContact::convolve(const RealField& in, RealField& out, double scale) {
  plan_->forward(in, spectrum_);
  auto* s = spectrum_.data();
  const double* k = kernel_.data();
  const std::size_t n = kernel_.size();
#pragma omp parallel for simd schedule(static)
  for (std::size_t m = 0; m < n; ++m) s[m] *= scale * k[m];
  plan_->backward_unnormalized(spectrum_, out);
}

ContactResult NormalContact::solve_mean_pressure(double p0, const ContactOptions& opt) {
  if (!(p0 >= 0.0) || !std::isfinite(p0))
    throw InputError(fmt::format("normal contact: mean pressure {} is not allowed; allowed: ≥ 0", p0));
  if (!(opt.tolerance > 0.0)) throw InputError("normal contact: the tolerance must be > 0");
  history_.clear();
  const std::size_t n = h_.size();
  double* p = p_.data();
  double* u = u_.data();
  double* t = t_.data();
  const double* h = h_.data();
  const double* r = r_.data();

  if (p0 == 0.0) {
    p_.fill(0.0);
    u_.fill(0.0);
    return finish(0, 0.0, -h_max_);  // the summit just touches: δ = 0
  }
  // Warm start: the previous pressure rescaled to p0; else uniform p0.
  double mean = 0.0;
  for (std::size_t k = 0; k < n; ++k) mean += p[k];
  mean /= static_cast<double>(n);
  double alpha = 1.0;  // the pressure is α·p_ (rescaling folded into the next passes)
  if (mean > 0.0 && std::isfinite(mean))
    alpha = p0 / mean;
  else
    p_.fill(p0);
  std::fill(t, t + n, 0.0);

  bool conjugate = false;  // δ of Polonsky–Keer: 0 restarts steepest descent
  double g_norm_old = 1.0, shift = 0.0;
  for (int it = 0; it < opt.max_iterations; ++it) {
    convolve(p_, u_, alpha);  // u = K (α p)

    // Pass 1: mean gap on the contact S = {p > 0}, and Σ_S (g − ḡ)² by shifted sums.
    double n_s = 0.0, sum = 0.0, sum2 = 0.0;
#pragma omp parallel for reduction(+ : n_s, sum, sum2) schedule(static)
    for (std::size_t k = 0; k < n; ++k)
      if (p[k] > 0.0) {
        const double d = u[k] - h[k] - shift;
        n_s += 1.0;
        sum += d;
        sum2 += d * d;
      }
    if (n_s == 0.0) throw NumericalError(kSolver, it, "contact area", "the contact vanished (no point with p > 0)");
    const double g_mean = shift + sum / n_s;
    const double g_norm = std::max(0.0, sum2 - sum * sum / n_s);
    shift = g_mean;

    // Pass 2: error, search direction t and its products.
    const double beta = conjugate ? g_norm / g_norm_old : 0.0;
    double err_num = 0.0, p_sum = 0.0, gt = 0.0, t_sum = 0.0, penetrating = 0.0;
#pragma omp parallel for reduction(+ : err_num, p_sum, gt, t_sum, penetrating) schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
      const double g = u[k] - h[k] - g_mean;
      if (p[k] > 0.0) {
        err_num += p[k] * std::abs(g);
        p_sum += p[k];
        const double tk = g + beta * t[k];
        t[k] = tk;
        gt += g * tk;
        t_sum += tk;
      } else {
        t[k] = 0.0;
        penetrating += g < 0.0 ? 1.0 : 0.0;
      }
    }
    const double error = err_num / (p_sum * h_rms_);
    if (!std::isfinite(error)) throw NumericalError(kSolver, it, "orthogonality error", "not finite (NaN in u or p)");
    history_.push_back(error);
    if (history_.size() > kHistory) history_.erase(history_.begin());
    if (error < opt.tolerance && penetrating == 0.0) {
      for (std::size_t k = 0; k < n; ++k) p[k] *= alpha;
      return finish(it, error, g_mean);
    }
    g_norm_old = g_norm;

    convolve(t_, r_, 1.0);  // r = K t

    // Pass 3: step length τ = Σ_S g t / Σ_S (r − r̄) t.
    double r_sum = 0.0, rt = 0.0;
#pragma omp parallel for reduction(+ : r_sum, rt) schedule(static)
    for (std::size_t k = 0; k < n; ++k)
      if (p[k] > 0.0) {
        r_sum += r[k];
        rt += r[k] * t[k];
      }
    const double denom = rt - (r_sum / n_s) * t_sum;
    const double tau = gt / denom;
    if (!std::isfinite(tau) || !(denom > 0.0))
      throw NumericalError(kSolver, it, "step length", fmt::format("τ = {} (Σ r t = {})", tau, denom));

    // Pass 4: descend, project on p ≥ 0, re-admit penetrating points, sum for the mean.
    double overlap = 0.0, new_sum = 0.0;
#pragma omp parallel for reduction(+ : overlap, new_sum) schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
      double pk = p[k] > 0.0 ? std::max(alpha * p[k] - tau * t[k], 0.0) : 0.0;
      if (pk == 0.0) {
        const double g = u[k] - h[k] - g_mean;
        if (g < 0.0) {
          pk = -tau * g;
          overlap += 1.0;
        }
      }
      p[k] = pk;
      new_sum += pk;
    }
    conjugate = overlap == 0.0;
    if (!(new_sum > 0.0)) throw NumericalError(kSolver, it, "pressure", "all pressures vanished");
    alpha = p0 * static_cast<double>(n) / new_sum;  // impose ⟨p⟩ = p0 (A.6c)
  }
  throw NumericalError(kSolver, opt.max_iterations, "orthogonality error",
                       fmt::format("no convergence to {:g}; last errors: {:.3g}", opt.tolerance,
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
  ContactResult r;
  r.iterations = iterations;
  r.error = error;
  r.mean_pressure = p_sum / static_cast<double>(n);
  r.contact_fraction = contact / static_cast<double>(n);
  r.interference = h_max_ + g_mean;
  r.elastic_energy = 0.5 * work * grid().cell_area();
  return r;
}

namespace {
struct RootData {
  NormalContact* contact;
  const ContactOptions* options;
  double target;
};
double interference_residual(double p0, void* params) {
  auto* d = static_cast<RootData*>(params);
  return d->contact->solve_mean_pressure(p0, *d->options).interference - d->target;
}
}  // namespace

ContactResult NormalContact::solve_interference(double delta, const ContactOptions& opt) {
  if (!std::isfinite(delta)) throw InputError("normal contact: the interference must be finite");
  if (delta <= 0.0) return solve_mean_pressure(0.0, opt);
  // Bracket: δ(p0) grows with p0 and δ → 0⁺ as p0 → 0 for a surface with one summit.
  const double scale = e_star_ * std::max(delta, 1e-300) / std::max(grid().lx, grid().ly);
  double lo = 0.0, hi = scale;
  for (int k = 0; solve_mean_pressure(hi, opt).interference < delta; ++k) {
    lo = hi;
    hi *= 4.0;
    if (k > 200) throw NumericalError(kSolver, k, "interference", "cannot bracket the imposed interference");
  }
  RootData data{this, &opt, delta};
  gsl_function f{&interference_residual, &data};
  gsl_root_fsolver* s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  gsl_error_handler_t* old = gsl_set_error_handler_off();
  gsl_root_fsolver_set(s, &f, lo, hi);
  int status = GSL_CONTINUE;
  int iter = 0;
  for (; status == GSL_CONTINUE && iter < 200; ++iter) {
    gsl_root_fsolver_iterate(s);
    status = gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s), 0.0, 1e-12);
  }
  const double p0 = gsl_root_fsolver_root(s);
  gsl_root_fsolver_free(s);
  gsl_set_error_handler(old);
  if (status != GSL_SUCCESS) throw NumericalError(kSolver, iter, "interference", "Brent search did not converge");
  return solve_mean_pressure(p0, opt);
}

}  // namespace wearscale::bem
