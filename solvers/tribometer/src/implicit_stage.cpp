// The implicit stage of the adaptive integrator: z = a + γ f(s, z) as one
// contact solve, the stage's wear being a compliance added to the half-space's.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "stage_compliance.hpp"
#include "wear_share.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/tribometer/pin_on_disc.hpp"

namespace wearscale::tribometer {

namespace {
constexpr const char* kModel = kPinOnDiscModel;
constexpr int kMaterialSweeps = 4;      // re-solves of an implicit stage whose materials changed
constexpr int kDiscIterations = 50;     // fixed-point passes on the disc's share of the stage compliance
constexpr double kDiscTolerance = 1e-12;
constexpr int kStageIterations = 3000;   // BEM iterations of a stage solve before a shorter stage is asked for
}  // namespace

void PinOnDisc::solve_stage(double s, const double* a, double gamma, double* z, double* rate,
                            PinOnDiscSample& sample, const std::vector<char>* layer) {
  if (!(gamma > 0.0) || !std::isfinite(gamma) || !std::isfinite(s))
    throw NumericalError(kModel, solves_, "implicit stage", fmt::format("γ = {}, s = {}", gamma, s));
  if (track_ > 0) return solve_track_stage(s, a, gamma, z, rate, sample, layer);
  const Grid2D& g = grid();
  const std::size_t np = pin_.size(), nx = g.nx, ny = g.ny;
  const double share_layer = pin_share(setup_.on_layer), share_substrate = pin_share(setup_.on_substrate);
  const double disc_scale = g.lx / setup_.path_length;
  const std::vector<double> warm_pressure(contact_.pressure().begin(), contact_.pressure().end());
  const double warm_shift = contact_.warm_gap_shift();
  const std::vector<double> state_before = state();
  const double s_before = s_;
  auto give_up = [&](const NumericalError& e) {
    contact_.set_added_compliance(nullptr);
    contact_.set_warm_start(warm_pressure, warm_shift);
    set_state(state_before.data(), s_before);
    throw StageNotSolved(e.solver(), e.step(), e.quantity(), e.detail());
  };
  set_state(a, s);
  build_profile(s);
  const RealField surface = profile_;  // h of the stage's explicit part a
  if (layer != nullptr)
    layer_ = *layer;
  else
    classify(s, a + np, layer_);
  if (!compliance_) compliance_ = std::make_unique<StageCompliance>();
  StageCompliance& A = *compliance_;
  A.ny = ny;
  A.kappa = contact_.body().self_compliance();
  A.w.assign(g.size(), 0.0);
  A.c.assign(nx, 0.0);
  std::vector<double> v(g.size()), residual(nx, 0.0), next(nx);  // disc rate per pressure; its column part beyond c
  std::vector<char> consistent;
  bem::ContactResult r;
  for (int sweep = 0; sweep < kMaterialSweeps; ++sweep) {
    // The compliance of the stage's wear on these materials: w = γ s/p_crit on
    // the pin (9.23)-(9.24); on the disc γ (1 − s)/p_crit averaged over the
    // column and scaled by L/L_path (9.25), its mean over the column (weighted
    // by the last pressure) as c and the rest iterated on as a known shift.
    const RealField& warm = contact_.pressure();
    for (std::size_t i = 0; i < nx; ++i) {
      double weighted = 0.0, weight = 0.0, plain = 0.0;
      for (std::size_t j = 0; j < ny; ++j) {
        const std::size_t k = g.index(i, j);
        const bool on = layer_[k] != 0;
        const auto& law = on ? setup_.on_layer : setup_.on_substrate;
        const double share = on ? share_layer : share_substrate;
        A.w[k] = gamma * share / law.p_crit;
        v[k] = gamma * (1.0 - share) / law.p_crit * disc_scale;
        weighted += v[k] * warm[k];
        weight += warm[k];
        plain += v[k];
      }
      A.c[i] = weight > 0.0 ? weighted / weight : plain / static_cast<double>(ny);
    }
    A.set_diagonal();
    auto column_residual = [&](const RealField& p, std::vector<double>& out) {
      for (std::size_t i = 0; i < nx; ++i) {
        double sum = 0.0;
        for (std::size_t j = 0; j < ny; ++j) sum += (v[g.index(i, j)] - A.c[i]) * p[g.index(i, j)];
        out[i] = sum / static_cast<double>(ny);
      }
    };
    column_residual(warm, residual);
    contact_.set_added_compliance(&A);
    for (int pass = 0;; ++pass) {
      for (std::size_t i = 0; i < nx; ++i)
        for (std::size_t j = 0; j < ny; ++j) profile_(i, j) = surface(i, j) - residual[i];
      try {
        // Preconditioned by the stage's own M ≈ (K + A)⁻¹ (StageCompliance), to
        // the stage tolerance.
        r = solve_contact(s, std::min(kStageIterations, setup_.max_iterations),
                          setup_.stage_preconditioner ? bem::ContactMethod::PreconditionedCG
                                                      : bem::ContactMethod::PolonskyKeer,
                          setup_.stage_tolerance);
      } catch (const NumericalError& e) {
        give_up(e);
      }
      column_residual(contact_.pressure(), next);
      double change = 0.0, scale = 0.0;
      for (std::size_t i = 0; i < nx; ++i) {
        change = std::max(change, std::abs(next[i] - residual[i]));
        scale = std::max(scale, A.c[i] * setup_.normal_load / g.area());
      }
      residual = next;
      if (change <= kDiscTolerance * scale) break;
      if (pass + 1 == kDiscIterations)
        give_up(NumericalError(kModel, solves_, "implicit stage",
                               fmt::format("the disc's wear did not settle in {} passes at s = {:g} m (change {:.3g} "
                                           "of {:.3g})",
                                           kDiscIterations, s, change, scale)));
    }
    contact_.set_added_compliance(nullptr);
    // z = a + γ f(z): the surfaces worn by the stage's pressure.
    const RealField& p = contact_.pressure();
    for (std::size_t k = 0; k < np; ++k) z[k] = a[k] + A.w[k] * p[k];
    for (std::size_t i = 0; i < nx; ++i) {
      double sum = 0.0;
      for (std::size_t j = 0; j < ny; ++j) sum += v[g.index(i, j)] * p[g.index(i, j)];
      z[np + i] = a[np + i] - sum / static_cast<double>(ny);
    }
    if (layer != nullptr) break;
    classify(s, z + np, consistent);
    if (consistent == layer_) break;
    layer_ = consistent;
  }
  finish_stage(s, a, gamma, z, rate, sample, r.iterations, consistent);
}

// After a stage's solve (z's surfaces and materials set): the rate at z —
// the disc's part, a column's on the averaged track, spread over the strip
// cells the window reads on a resolved one —, the volumes and ∫μ ds stepped
// with it, the sample at z, and what derivative() may reuse at z.
void PinOnDisc::finish_stage(double s, const double* a, double gamma, double* z, double* rate,
                             PinOnDiscSample& sample, int iterations, std::vector<char>& consistent) {
  const std::size_t np = pin_.size(), tail = np + disc_.size();
  std::copy(a + tail, a + tail + 3, z + tail);  // the volumes and ∫μ ds follow below
  set_state(z, s);
  rates(s, sample, &pin_rate_, &disc_rate_);  // the pressure solved is z's contact
  sample.iterations = iterations;
  std::copy(pin_rate_.begin(), pin_rate_.end(), rate);
  if (track_ > 0)
    spread_on_track(s, rate + np);
  else
    for (std::size_t i = 0; i < disc_.size(); ++i) rate[np + i] = -disc_rate_[i];
  rate[tail] = last_pin_volume_rate_;
  rate[tail + 1] = last_disc_volume_rate_;
  rate[tail + 2] = sample.friction;
  for (std::size_t k = tail; k < tail + 3; ++k) z[k] = a[k] + gamma * rate[k];
  set_state(z, s);
  sample.pin_wear = pin_wear_;
  sample.disc_wear = disc_wear_;
  sample.friction_integral = friction_integral_;
  // Kept for derivative() at z (the next step's first stage), when z's own
  // materials are those the stage wore with.
  classify(s, z + np, consistent);
  stage_valid_ = consistent == layer_;
  if (stage_valid_) {
    stage_state_.assign(z, z + state_size());
    stage_rate_.assign(rate, rate + state_size());
    stage_s_ = s;
    stage_sample_ = sample;
  }
}

}  // namespace wearscale::tribometer
