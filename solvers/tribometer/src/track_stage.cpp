// The implicit stage of the adaptive integrator on a resolved track:
// z = a + γ f(s, z) as one contact solve, the stage's wear of the pin and of
// the strip cells under the window being a compliance added to the half-space's.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "track_stage_compliance.hpp"
#include "wear_share.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/tribometer/pin_on_disc.hpp"

namespace wearscale::tribometer {

namespace {
constexpr const char* kModel = kPinOnDiscModel;
constexpr int kMaterialSweeps = 4;     // re-solves of an implicit stage whose materials changed
constexpr int kDiscIterations = 50;    // fixed-point passes on the asymmetric part of the strip's compliance
constexpr double kDiscTolerance = 1e-12;
constexpr int kStageIterations = 3000;  // BEM iterations of a stage solve before a shorter stage is asked for
}  // namespace

void PinOnDisc::solve_track_stage(double s, const double* a, double gamma, double* z, double* rate,
                                  PinOnDiscSample& sample, const std::vector<char>* layer) {
  const Grid2D& g = grid();
  const std::size_t np = pin_.size(), nd = disc_.size(), nx = g.nx, ny = g.ny;
  const double share_layer = pin_share(setup_.on_layer), share_substrate = pin_share(setup_.on_substrate);
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
  // Where the window reads the strip at s (as disc_height and spread_on_track do).
  const double at = s / g.dx(), base = std::floor(at), f = at - base;
  const auto first = static_cast<std::size_t>(std::fmod(base, static_cast<double>(track_)));
  if (!track_compliance_) track_compliance_ = std::make_unique<TrackStageCompliance>();
  TrackStageCompliance& A = *track_compliance_;
  A.nx = nx;
  A.ny = ny;
  A.c0 = (1.0 - f) * (1.0 - f) + f * f;
  A.c1 = f * (1.0 - f);
  A.wrap = track_ == ny;
  A.kappa = setup_.stage_preconditioner ? contact_.body().self_compliance() : 0.0;
  A.w.assign(g.size(), 0.0);
  A.v.assign(g.size(), 0.0);
  RealField shift(g), next(g);  // the asymmetric part of the strip's compliance, applied to the last pressure
  std::vector<char> consistent;
  bem::ContactResult r;
  // c1 (v_{j±1} − √(v_j v_{j±1})) p_{j±1}: the strip's wear under row j beyond the symmetric part.
  auto asymmetric = [&](const RealField& p, RealField& out) {
    for (std::size_t i = 0; i < nx; ++i)
      for (std::size_t j = 0; j < ny; ++j) {
        const std::size_t k = g.index(i, j);
        auto term = [&](std::size_t o) {
          const std::size_t n = g.index(i, o);
          return A.c1 * (A.v[n] - std::sqrt(A.v[k] * A.v[n])) * p[n];
        };
        double sum = 0.0;
        if (j + 1 < ny || A.wrap) sum += term((j + 1) % ny);
        if (j > 0 || A.wrap) sum += term((j + ny - 1) % ny);
        out[k] = sum;
      }
  };
  for (int sweep = 0; sweep < kMaterialSweeps; ++sweep) {
    // The compliance of the stage's wear on these materials: w = γ s/p_crit on
    // the pin (9.23)-(9.24), v = γ (1 − s)/p_crit on the strip (9.25).
    for (std::size_t k = 0; k < g.size(); ++k) {
      const bool on = layer_[k] != 0;
      const auto& law = on ? setup_.on_layer : setup_.on_substrate;
      const double share = on ? share_layer : share_substrate;
      A.w[k] = gamma * share / law.p_crit;
      A.v[k] = gamma * (1.0 - share) / law.p_crit;
    }
    A.prepare();
    asymmetric(contact_.pressure(), shift);
    contact_.set_added_compliance(&A);
    for (int pass = 0;; ++pass) {
      for (std::size_t k = 0; k < g.size(); ++k) profile_[k] = surface[k] - shift[k];
      try {
        r = solve_contact(s, std::min(kStageIterations, setup_.max_iterations),
                          setup_.stage_preconditioner ? bem::ContactMethod::PreconditionedCG
                                                      : bem::ContactMethod::PolonskyKeer,
                          setup_.stage_tolerance);
      } catch (const NumericalError& e) {
        give_up(e);
      }
      asymmetric(contact_.pressure(), next);
      double change = 0.0, scale = 0.0;
      const double p_mean = setup_.normal_load / g.area();
      for (std::size_t k = 0; k < g.size(); ++k) {
        change = std::max(change, std::abs(next[k] - shift[k]));
        scale = std::max(scale, A.v[k] * p_mean);
      }
      shift = next;
      if (change <= kDiscTolerance * scale) break;
      if (pass + 1 == kDiscIterations)
        give_up(NumericalError(kModel, solves_, "implicit stage",
                               fmt::format("the strip's wear did not settle in {} passes at s = {:g} m (change {:.3g} "
                                           "of {:.3g})",
                                           kDiscIterations, s, change, scale)));
    }
    contact_.set_added_compliance(nullptr);
    // z = a + γ f(z): the surfaces worn by the stage's pressure.
    const RealField& p = contact_.pressure();
    for (std::size_t k = 0; k < np; ++k) z[k] = a[k] + A.w[k] * p[k];
    std::copy(a + np, a + np + nd, z + np);
    for (std::size_t i = 0; i < nx; ++i)
      for (std::size_t j = 0; j < ny; ++j) {
        const std::size_t k = g.index(i, j), m = (first + j) % track_;
        const double worn = A.v[k] * p[k];
        z[np + i * track_ + m] -= (1.0 - f) * worn;
        z[np + i * track_ + (m + 1) % track_] -= f * worn;
      }
    if (layer != nullptr) break;
    classify(s, z + np, consistent);
    if (consistent == layer_) break;
    layer_ = consistent;
  }
  finish_stage(s, a, gamma, z, rate, sample, r.iterations, consistent);
}

}  // namespace wearscale::tribometer
