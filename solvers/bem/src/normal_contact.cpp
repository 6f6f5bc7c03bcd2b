#include "wearscale/bem/normal_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/bem/roughness.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/roots.hpp"

namespace wearscale::bem {

namespace {
constexpr const char* kSolver = "bem/normal-contact (Polonsky–Keer)";
constexpr std::size_t kHistory = 12;
}  // namespace

NormalContact::NormalContact(const RealField& surface, double e_star)
    : h_(surface), p_(surface.grid()), u_(surface.grid()), t_(surface.grid()),
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
  // Displacement of a cell under a unit pressure on itself: Σ_q K(q) over the full spectrum.
  self_compliance_ = 0.0;
  const std::size_t cols = g.spectral_ny(), last = g.ny % 2 == 0 ? cols - 1 : cols;
  for (std::size_t m = 0; m < kernel_.size(); ++m) {
    const std::size_t j = m % cols;
    self_compliance_ += (j == 0 || j == last ? 1.0 : 2.0) * kernel_[m];
  }
  set_surface(surface);
}

void NormalContact::set_surface(const RealField& surface) {
  if (!(surface.grid() == h_.grid())) throw std::invalid_argument("NormalContact::set_surface: grid changed");
  h_ = surface;
  double max = -std::numeric_limits<double>::infinity();
  for (double v : h_) {
    if (!std::isfinite(v)) throw InputError("normal contact: the surface has a NaN or infinite height");
    max = std::max(max, v);
  }
  h_rms_ = h_rms(h_);  // the scale of the convergence measure
  if (!(h_rms_ > 0.0)) h_rms_ = 1.0;
  h_max_ = max;
}

void NormalContact::reset() { p_.fill(0.0); }

void NormalContact::set_warm_start(std::span<const double> pressure, double gap_shift) {
  if (pressure.size() != p_.size())
    throw InputError(fmt::format("normal contact: a warm start of {} pressures for a grid of {} points",
                                 pressure.size(), p_.size()));
  for (double v : pressure)
    if (!std::isfinite(v) || v < 0.0) throw InputError("normal contact: a warm-start pressure is negative, NaN or infinite");
  if (!std::isfinite(gap_shift)) throw InputError("normal contact: the warm-start mean gap is not finite");
  std::copy(pressure.begin(), pressure.end(), p_.begin());
  gap_shift_ = gap_shift;
}

void NormalContact::convolve(const RealField& in, RealField& out, double scale) {
  plan_->forward(in, spectrum_);
  auto* s = spectrum_.data();
  const double* k = kernel_.data();
  const std::size_t n = kernel_.size();
#pragma omp parallel for simd schedule(static)
  for (std::size_t m = 0; m < n; ++m) s[m] *= scale * k[m];
  plan_->backward_unnormalized(spectrum_, out);
}

double NormalContact::quadratic_form(const RealField& t) {
  plan_->forward(t, spectrum_);
  const Grid2D& g = grid();
  const std::size_t cols = g.spectral_ny(), rows = g.nx;
  const std::size_t last = g.ny % 2 == 0 ? cols - 1 : cols;  // the Nyquist column is its own mirror
  const auto* s = spectrum_.data();
  const double* k = kernel_.data();
  double sum = 0.0;
#pragma omp parallel for reduction(+ : sum) schedule(static)
  for (std::size_t i = 0; i < rows; ++i) {
    double row = 0.0;
    for (std::size_t j = 0; j < cols; ++j) {
      const std::size_t m = i * cols + j;
      const double w = (j == 0 || j == last) ? 1.0 : 2.0;  // modes stored once for ±q_y
      row += w * k[m] * std::norm(s[m]);
    }
    sum += row;
  }
  return sum;  // Σ_x t (K t) = (1/N) Σ_q K(q) |t̂(q)|², the 1/N being in the kernel
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

  double first_error = 0.0;
  bool conjugate = false;  // δ of Polonsky–Keer: false restarts steepest descent
  double g_norm_old = 0.0;
  double& shift = gap_shift_;  // the last mean gap: carried across solves (warm start)
  for (int it = 0; it < opt.max_iterations; ++it) {
    convolve(p_, u_, alpha);  // u = K (α p)
    if (added_ != nullptr) added_->add(p_, alpha, u_);

    // Pass 1 over the contact S = {p > 0}: mean gap ḡ, Σ_S (g − ḡ)² (by sums
    // shifted by the last ḡ, which keeps them free of cancellation), and the
    // mean of the previous direction on the new S.
    double n_s = 0.0, sum = 0.0, sum2 = 0.0, t_old_sum = 0.0;
#pragma omp parallel for simd reduction(+ : n_s, sum, sum2, t_old_sum) schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
      const double in = p[k] > 0.0 ? 1.0 : 0.0;
      const double d = (u[k] - h[k] - shift) * in;
      n_s += in;
      sum += d;
      sum2 += d * d;
      t_old_sum += t[k] * in;
    }
    if (n_s == 0.0) throw NumericalError(kSolver, it, "contact area", "the contact vanished (no point with p > 0)");
    const double g_mean = shift + sum / n_s;
    double g_norm = sum2 - sum * sum / n_s;
    if (!(g_norm > 64.0 * std::numeric_limits<double>::epsilon() * sum2)) {
      // The shift was far from the mean: the sums cancelled. Recompute exactly.
      g_norm = 0.0;
#pragma omp parallel for simd reduction(+ : g_norm) schedule(static)
      for (std::size_t k = 0; k < n; ++k) {
        const double d = p[k] > 0.0 ? u[k] - h[k] - g_mean : 0.0;
        g_norm += d * d;
      }
    }
    shift = g_mean;

    // Pass 2: error; conjugate direction t = g + β (t_old − ⟨t_old⟩_S) on S, 0
    // elsewhere. Projecting the direction to zero mean on S keeps the load
    // constant along it, so the step needs only t·Kt (no mean of K t on S).
    const double beta = conjugate && g_norm_old > 0.0 ? g_norm / g_norm_old : 0.0;
    const double t_old_mean = t_old_sum / n_s;
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
    const double error = err_num / (p_sum * h_rms_);
    if (!std::isfinite(error)) throw NumericalError(kSolver, it, "orthogonality error", "not finite (NaN in u or p)");
    if (it == 0) first_error = error;
    history_.push_back(error);
    if (history_.size() > kHistory) history_.erase(history_.begin());
    if (error < opt.tolerance && penetrating == 0.0) {
      for (std::size_t k = 0; k < n; ++k) p[k] *= alpha;
      return finish(it, error, g_mean);
    }
    g_norm_old = g_norm;

    // Step length τ = Σ g t / Σ t (K t), the denominator by Parseval from the
    // spectrum of t: one forward FFT instead of a full convolution.
    const double tkt = quadratic_form(t_) + (added_ != nullptr ? added_->quadratic_form(t_) : 0.0);
    // No descent direction (a contact of one point, or a flat gap on S) while
    // points outside still penetrate: admit them with a cell's own stiffness.
    const double tau = (tkt == 0.0 && gt == 0.0) ? 1.0 / self_compliance_ : gt / tkt;
    if (!std::isfinite(tau) || !(tkt > 0.0 || gt == 0.0))
      throw NumericalError(kSolver, it, "step length", fmt::format("τ = {} (t·Kt = {})", tau, tkt));

    // Pass 3: descend, project on p ≥ 0, re-admit penetrating points, sum for the mean.
    double overlap = 0.0, new_sum = 0.0;
#pragma omp parallel for simd reduction(+ : overlap, new_sum) schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
      const double descended = p[k] > 0.0 ? std::max(alpha * p[k] - tau * t[k], 0.0) : 0.0;
      const double g = u[k] - h[k] - g_mean;
      const bool readmit = descended == 0.0 && g < 0.0;
      const double pk = readmit ? -tau * g : descended;
      overlap += readmit ? 1.0 : 0.0;
      p[k] = pk;
      new_sum += pk;
    }
    conjugate = overlap == 0.0;
    if (!(new_sum > 0.0)) throw NumericalError(kSolver, it, "pressure", "all pressures vanished");
    alpha = p0 * static_cast<double>(n) / new_sum;  // impose ⟨p⟩ = p0 (A.6c)
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
  ContactResult r;
  r.iterations = iterations;
  r.error = error;
  r.mean_pressure = p_sum / static_cast<double>(n);
  r.contact_fraction = contact / static_cast<double>(n);
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
  for (int k = 0; solve_mean_pressure(hi, opt).interference < delta; ++k) {
    lo = hi;
    hi *= 4.0;
    if (k > 200) throw NumericalError(kSolver, k, "interference", "cannot bracket the imposed interference");
  }
  const double p0 = find_root([&](double p) { return solve_mean_pressure(p, opt).interference - delta; }, lo, hi,
                              1e-12 * hi, kSolver);
  return solve_mean_pressure(p0, opt);
}

}  // namespace wearscale::bem
