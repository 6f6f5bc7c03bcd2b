#include "wearscale/bem/frictional_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/bem/roughness.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/memory_limit.hpp"

namespace wearscale::bem {

namespace {
constexpr const char* kSolver = "bem/frictional-contact (Algorithm 1)";
constexpr std::size_t kHistory = 12;
// A point with ‖p_T‖ ≥ (1 − kOnCone) p_T,max is on the friction cone (sliding).
constexpr double kOnCone = 1e-9;
// Updates of the friction bound without halving its change before it is kept.
constexpr int kStalledUpdates = 8;
// A block's conjugacy is restarted when its residual grows by more than this.
constexpr double kBetaMax = 10.0;
// Per-point state during the iterations; kReleased: on the cone but slipping
// the wrong way, so its tangential traction is set free again (as stick).
enum : std::uint8_t { kOpen = 0, kStick = 1, kSlip = 2, kReleased = 3 };

// ‖(x, y)‖ without std::hypot's overflow care (tractions and displacements
// are far from it), which costs more than the rest of a pass.
inline double norm(double x, double y) { return std::sqrt(x * x + y * y); }

void check_grid(const Grid2D& g) {
  if (g.nx < 2 || g.ny < 2) throw InputError("frictional contact: the grid needs at least 2×2 points");
}

void check_material(double e, double nu) {
  if (!(e > 0.0) || !std::isfinite(e))
    throw InputError(fmt::format("frictional contact: Young's modulus E = {} is not allowed; allowed: E > 0", e));
  if (!(nu > -1.0 && nu <= 0.5))
    throw InputError(fmt::format(
        "frictional contact: Poisson's ratio ν = {} is not allowed; allowed: −1 < ν ≤ 0.5", nu));
}

std::unique_ptr<TractionOperator> serial_body(const Grid2D& g, double young, double poisson) {
  check_material(young, poisson);
  check_grid(g);
  return std::make_unique<HalfSpaceTraction>(g, young, poisson);
}
}  // namespace

// As NormalContact's: 640 B per point (the contact study's estimate with friction), checked before allocating.
static const Grid2D& within_memory(const Grid2D& g) {
  require_memory(640.0 * static_cast<double>(g.size()),
                 fmt::format("a frictional contact of {} × {} points", g.nx, g.ny), "use a smaller grid");
  return g;
}

FrictionalContact::FrictionalContact(const RealField& surface, double young, double poisson, FrictionLaw law)
    : FrictionalContact(serial_body(within_memory(surface.grid()), young, poisson), surface, law) {}

FrictionalContact::FrictionalContact(std::unique_ptr<TractionOperator> body, const RealField& surface,
                                     FrictionLaw law)
    : h_(surface), young_(body->young()), poisson_(body->poisson()), law_(law), p_(surface.grid()),
      u_(surface.grid()), t_(surface.grid()), t_old_(surface.grid()), d_(surface.grid()), slip_(surface.grid()),
      gap_(surface.grid()), map_(surface.grid()), bound_(surface.grid()), state_(surface.size(), kOpen),
      body_(std::move(body)) {
  if (!(surface.grid() == body_->local_grid()))
    throw std::invalid_argument("FrictionalContact: the surface is not on the rows the body holds");
  check_material(young_, poisson_);
  check_grid(body_->grid());
  const SurfaceScale scale = surface_scale(*body_, h_, "frictional contact");
  h_rms_ = scale.h_rms;
  h_max_ = scale.h_max;
}

void FrictionalContact::reset() {
  for (RealField* f : {&p_.x, &p_.y, &p_.z}) f->fill(0.0);
}

bool FrictionalContact::project_tangential(double target_x, double target_y, int iteration, bool free_only) {
  const std::size_t n = h_.size();
  double* px = p_.x.data();
  double* py = p_.y.data();
  const double* pn = p_.z.data();
  const std::uint8_t* state = state_.data();
  const double* bound = bound_.data();
  // Points on the cone keep their traction; the others (stick, released, newly
  // admitted) take the shift. cap: ⟨p_T,max⟩; the sums are over the cell.
  double cap = 0.0, cap_free = 0.0, fixed_x = 0.0, fixed_y = 0.0;
  std::size_t n_free = 0;
#pragma omp parallel for reduction(+ : cap, cap_free, fixed_x, fixed_y, n_free) schedule(static)
  for (std::size_t k = 0; k < n; ++k) {
    const double b = (pn[k] > 0.0 ? bound[k] : 0.0);
    cap += b;
    if (!(b > 0.0)) continue;
    if (free_only && state[k] == kSlip) {
      const double r = norm(px[k], py[k]), s = r > b ? b / r : 1.0;
      fixed_x += s * px[k];
      fixed_y += s * py[k];
    } else {
      cap_free += b;
      n_free += 1;
    }
  }
  sum(cap, cap_free, fixed_x, fixed_y, n_free);
  const double nn = points();
  capacity_ = cap / nn;
  const double q0 = norm(target_x, target_y);
  all_sliding_ = false;
  overloaded_ = false;
  if (q0 == 0.0 && cap == 0.0) {
    std::fill(px, px + n, 0.0);
    std::fill(py, py + n, 0.0);
    return true;
  }
  if (q0 > 0.0 && q0 >= capacity_ * (1.0 - 1e-12)) {
    // Every point at its limit along the load: full sliding, or more than friction can carry.
    const double ex = target_x / q0, ey = target_y / q0;
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
      const double b = (pn[k] > 0.0 ? bound[k] : 0.0);
      px[k] = b * ex;
      py[k] = b * ey;
    }
    all_sliding_ = true;
    overloaded_ = q0 > capacity_ * (1.0 + 1e-9);
    return !overloaded_;
  }
  // The free points must carry what the others do not; if they cannot, all move.
  if (free_only && (n_free == 0 || norm(target_x * nn - fixed_x, target_y * nn - fixed_y) >= cap_free)) {
    return project_tangential(target_x, target_y, iteration, false);
  }
  // Projection on {‖p_T‖ ≤ p_T,max} ∩ {⟨p_T⟩ = target}: p_T = P(w + λ) at the
  // free points, P the projection on each point's disc, the shift λ found by
  // Newton's method on the monotone map λ ↦ Σ P(w + λ) (damped by halving).
  const double tol = 1e-11 * nn * std::max(q0, capacity_);  // above the rounding of the sums
  const double goal_x = target_x * nn - fixed_x, goal_y = target_y * nn - fixed_y;
  double lx = 0.0, ly = 0.0, step_x = 0.0, step_y = 0.0, scale = 1.0, f_prev = INFINITY;
  double base_x = 0.0, base_y = 0.0;
  for (int newton = 0; newton < 200; ++newton) {
    double fx = 0.0, fy = 0.0, jxx = 0.0, jyy = 0.0, jxy = 0.0;
#pragma omp parallel for reduction(+ : fx, fy, jxx, jyy, jxy) schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
      const double b = (pn[k] > 0.0 ? bound[k] : 0.0);
      if (!(b > 0.0) || (free_only && state[k] == kSlip)) continue;
      const double vx = px[k] + lx, vy = py[k] + ly, r = norm(vx, vy);
      if (r <= b) {
        fx += vx;
        fy += vy;
        jxx += 1.0;
        jyy += 1.0;
      } else {
        const double s = b / r, nx = vx / r, ny = vy / r;
        fx += s * vx;
        fy += s * vy;
        jxx += s * (1.0 - nx * nx);
        jyy += s * (1.0 - ny * ny);
        jxy -= s * nx * ny;
      }
    }
    sum(fx, fy, jxx, jyy, jxy);
    fx -= goal_x;
    fy -= goal_y;
    const double f_norm = norm(fx, fy);
    if (f_norm <= tol) {
      // The last residual goes to the points strictly inside their disc (a
      // shift of order 1e-11 of the load, which keeps them inside).
      double n_in = 0.0;
#pragma omp parallel for reduction(+ : n_in) schedule(static)
      for (std::size_t k = 0; k < n; ++k) {
        const double b = (pn[k] > 0.0 ? bound[k] : 0.0);
        const bool shifted = !(free_only && state[k] == kSlip);
        const double vx = px[k] + (shifted ? lx : 0.0), vy = py[k] + (shifted ? ly : 0.0), r = norm(vx, vy);
        const double s = !(b > 0.0) ? 0.0 : (r <= b ? 1.0 : b / r);
        px[k] = s * vx;
        py[k] = s * vy;
        n_in += (shifted && b > 0.0 && r < b * (1.0 - 1e-6)) ? 1.0 : 0.0;
      }
      sum(n_in);
      if (n_in > 0.0) {
        double sum_x = 0.0, sum_y = 0.0;
#pragma omp parallel for reduction(+ : sum_x, sum_y) schedule(static)
        for (std::size_t k = 0; k < n; ++k) {
          sum_x += px[k];
          sum_y += py[k];
        }
        sum(sum_x, sum_y);
        const double cx = (target_x * nn - sum_x) / n_in, cy = (target_y * nn - sum_y) / n_in;
#pragma omp parallel for schedule(static)
        for (std::size_t k = 0; k < n; ++k) {
          const double b = (pn[k] > 0.0 ? bound[k] : 0.0);
          const bool shifted = !(free_only && state[k] == kSlip);
          if (shifted && b > 0.0 && norm(px[k], py[k]) < b * (1.0 - 1e-6)) {
            px[k] += cx;
            py[k] += cy;
          }
        }
      }
      return true;
    }
    if (f_norm > f_prev && scale > 1e-6) {  // overshoot: halve the last step
      scale *= 0.5;
      lx = base_x - scale * step_x;
      ly = base_y - scale * step_y;
      continue;
    }
    f_prev = f_norm;
    base_x = lx;
    base_y = ly;
    scale = 1.0;
    const double det = jxx * jyy - jxy * jxy;
    if (det > 1e-12 * (jxx * jxx + jyy * jyy) && det > 0.0) {
      step_x = (jyy * fx - jxy * fy) / det;
      step_y = (jxx * fy - jxy * fx) / det;
    } else {  // every point at its limit: move as if all were free
      const double free = static_cast<double>(std::max<std::size_t>(n_free, 1));
      step_x = fx / free;
      step_y = fy / free;
    }
    lx = base_x - step_x;
    ly = base_y - step_y;
  }
  throw NumericalError(kSolver, iteration, "mean tangential traction",
                       fmt::format("the projection on the friction cone did not reach ⟨p_T⟩ = ({:g}, {:g}) Pa "
                                   "(capacity ⟨p_T,max⟩ = {:g} Pa)",
                                   target_x, target_y, capacity_));
}

void FrictionalContact::check_load(const MeanTraction& load) const {
  if (!(load.normal >= 0.0) || !std::isfinite(load.normal))
    throw InputError(
        fmt::format("frictional contact: mean normal traction {} is not allowed; allowed: ≥ 0", load.normal));
  if (!std::isfinite(load.x) || !std::isfinite(load.y))
    throw InputError("frictional contact: the mean tangential traction must be finite");
  const double q0 = norm(load.x, load.y);
  const bool coulomb = law_.kind() == FrictionLaw::Kind::Coulomb;
  const double mu = coulomb ? law_.parameter() : 0.0;
  if (q0 > 0.0 && (load.normal == 0.0 || (coulomb && q0 > mu * load.normal * (1.0 + 1e-12))))
    throw InputError(fmt::format(
        "frictional contact: the tangential load ‖⟨p_T⟩‖ = {:g} Pa exceeds what {} friction can carry at "
        "⟨p_N⟩ = {:g} Pa: the contact slides as a whole (gross sliding); "
        "allowed: ‖⟨p_T⟩‖ ≤ μ⟨p_N⟩ = {:g} Pa",
        q0, law_.to_string(), load.normal, mu * load.normal));
}

// Warm start: the previous traction rescaled to the new mean; else uniform.
// The friction bound of the first subproblem: σ_m,T (A.3), or μ p_N (A.2) of
// that traction (lagged; see the header).
void FrictionalContact::warm_start(const MeanTraction& load) {
  const std::size_t n = h_.size();
  double *px = p_.x.data(), *py = p_.y.data(), *pz = p_.z.data();
  double mean = 0.0;
  for (std::size_t k = 0; k < n; ++k) mean += pz[k];
  sum(mean);
  mean /= points();
  if (mean > 0.0 && std::isfinite(mean)) {
    const double alpha = load.normal / mean;
    for (std::size_t k = 0; k < n; ++k) {
      pz[k] *= alpha;
      px[k] *= alpha;
      py[k] *= alpha;
    }
  } else {
    p_.z.fill(load.normal);
    p_.x.fill(0.0);
    p_.y.fill(0.0);
  }
  for (std::size_t k = 0; k < n; ++k) bound_[k] = law_.max_tangential(pz[k]);
  for (RealField* f : {&t_.x, &t_.y, &t_.z, &t_old_.x, &t_old_.y, &t_old_.z}) f->fill(0.0);
  project_tangential(load.x, load.y, 0, false);
}

// Pass 1: gap shifts. Normal: the mean gap on the contact (Polonsky–Keer);
// tangential: the mean displacement of the stick zone I_s, the rigid
// tangential displacement δ_T (A.13). Without a stick zone, the contact's.
FrictionalContact::GapShifts FrictionalContact::measure_shifts(int iteration, bool stop) const {
  const std::size_t n = h_.size();
  const double *px = p_.x.data(), *py = p_.y.data(), *pz = p_.z.data();
  const double *ux = u_.x.data(), *uy = u_.y.data(), *uz = u_.z.data();
  const double *bound = bound_.data(), *h = h_.data();
  double n_c = 0.0, n_s = 0.0, sum_n = 0.0, sum_sx = 0.0, sum_sy = 0.0, sum_cx = 0.0, sum_cy = 0.0, sum_p = 0.0;
#pragma omp parallel for reduction(+ : n_c, n_s, sum_n, sum_sx, sum_sy, sum_cx, sum_cy, sum_p) schedule(static)
  for (std::size_t k = 0; k < n; ++k) {
    if (!(pz[k] > 0.0)) continue;
    n_c += 1.0;
    sum_p += pz[k];
    sum_n += uz[k] - h[k];
    sum_cx += ux[k];
    sum_cy += uy[k];
    if (bound[k] > 0.0 && norm(px[k], py[k]) < (1.0 - kOnCone) * bound[k]) {
      n_s += 1.0;
      sum_sx += ux[k];
      sum_sy += uy[k];
    }
  }
  double stops = stop ? 1.0 : 0.0;  // any process asked: every one stops here
  sum(n_c, n_s, sum_n, sum_sx, sum_sy, sum_cx, sum_cy, sum_p, stops);
  if (stops > 0.0) throw Interrupted(fmt::format("{}: stopped at iteration {} (a stop was requested)", kSolver, iteration));
  if (n_c == 0.0)
    throw NumericalError(kSolver, iteration, "contact area", "the contact vanished (no point with p_N > 0)");
  GapShifts s;
  s.contact_points = n_c;
  s.pressure_sum = sum_p;
  s.normal = sum_n / n_c;
  // Every point on the cone, yet the load is below what friction can carry:
  // a fan of sliding directions with no stick zone to refer the slip to.
  s.stick_zone_lost = n_s == 0.0 && !all_sliding_ && capacity_ > 0.0;
  const bool stick_zone = n_s > 0.0 && !all_sliding_;
  s.x = stick_zone ? sum_sx / n_s : sum_cx / n_c;
  s.y = stick_zone ? sum_sy / n_s : sum_cy / n_c;
  return s;
}

// Restarts the tangential traction from the same fraction of p_T,max everywhere.
void FrictionalContact::restart_tangential(const MeanTraction& load, int iteration, Iterate& state) {
  if (++state.restarts > 50)
    throw NumericalError(kSolver, iteration, "stick zone", "the stick zone vanished again after 50 restarts");
  const std::size_t n = h_.size();
  double *px = p_.x.data(), *py = p_.y.data();
  const double *pz = p_.z.data(), *bound = bound_.data();
  const double q0 = norm(load.x, load.y);
  const double ratio = capacity_ > 0.0 ? q0 / capacity_ : 0.0, ex = q0 > 0.0 ? load.x / q0 : 0.0,
               ey = q0 > 0.0 ? load.y / q0 : 0.0;
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < n; ++k) {
    const double b = pz[k] > 0.0 ? bound[k] : 0.0;
    px[k] = ratio * b * ex;
    py[k] = ratio * b * ey;
  }
  state.conjugate_n = state.conjugate_t = false;
}

// Pass 2: the gradient (A.13) of the shifted gap, projected on what each
// point may do. Stick points move freely. A point on the friction cone
// stays on it, its p_T only turning, unless it slides the wrong way
// (g_T·p_T > 0): then it is released into the stick zone.
FrictionalContact::Residual FrictionalContact::gradient(const GapShifts& shifts) {
  const std::size_t n = h_.size();
  const double *px = p_.x.data(), *py = p_.y.data(), *pz = p_.z.data();
  const double *ux = u_.x.data(), *uy = u_.y.data(), *uz = u_.z.data();
  const double *bound = bound_.data(), *h = h_.data();
  double *dx = d_.x.data(), *dy = d_.y.data(), *dz = d_.z.data();
  std::uint8_t* state = state_.data();
  const double sn = shifts.normal, sx = shifts.x, sy = shifts.y;
  const bool sliding = all_sliding_;
  double err_n = 0.0, err_t = 0.0, b_sum = 0.0, rn_new = 0.0, rt_new = 0.0, penetrating = 0.0;
#pragma omp parallel for reduction(+ : err_n, err_t, b_sum, rn_new, rt_new, penetrating) schedule(static)
  for (std::size_t k = 0; k < n; ++k) {
    const double gn = uz[k] - h[k] - sn;
    double ax = 0.0, ay = 0.0, an = 0.0;
    if (!(pz[k] > 0.0)) {
      state[k] = kOpen;
      penetrating += gn < 0.0 ? 1.0 : 0.0;
    } else {
      const double gx = ux[k] - sx, gy = uy[k] - sy;
      const double b = bound[k], r = norm(px[k], py[k]);
      err_n += pz[k] * std::abs(gn);
      err_t += b * norm(gx, gy) + px[k] * gx + py[k] * gy;  // (A.14), the slip direction checked
      b_sum += b;
      an = gn;
      if (!(b > 0.0)) {  // frictionless point: p_T stays 0
        state[k] = kSlip;
      } else if (r >= (1.0 - kOnCone) * b) {
        const double nx = px[k] / r, ny = py[k] / r, along = gx * nx + gy * ny;
        const bool release = along > 0.0 && !sliding;  // in full sliding p_T is fixed
        state[k] = release ? kReleased : kSlip;
        ax = release ? gx : (sliding ? 0.0 : gx - along * nx);
        ay = release ? gy : (sliding ? 0.0 : gy - along * ny);
      } else {
        state[k] = kStick;
        ax = gx;
        ay = gy;
      }
    }
    dx[k] = ax;
    dy[k] = ay;
    dz[k] = an;
    rn_new += an * an;
    rt_new += ax * ax + ay * ay;
  }
  sum(err_n, err_t, b_sum, rn_new, rt_new, penetrating);
  Residual r;
  r.error_n = err_n / (shifts.pressure_sum * h_rms_);
  r.error_t = (sliding || !(b_sum > 0.0)) ? 0.0 : err_t / (b_sum * h_rms_);
  r.error = r.error_n + r.error_t;
  r.rn = rn_new;
  r.rt = rt_new;
  r.penetrates = penetrating > 0.0;
  return r;
}

// A subproblem is solved (loosely while its bound is still far from the
// law's): compare its bound with the law's, and start the next one, or
// accept the solution (Solved) once the bound holds.
FrictionalContact::Subproblem FrictionalContact::check_subproblem(const Residual& res, const MeanTraction& load,
                                                                  int it, Iterate& state) {
  const double tolerance = tolerance_;
  const double subproblem_tolerance =
      state.settled ? tolerance : std::max(tolerance, 1e-2 * state.bound_change);
  if (!(res.error < subproblem_tolerance && !res.penetrates)) return Subproblem::Open;
  const std::size_t n = h_.size();
  const double nn = points(), q0 = norm(load.x, load.y);
  double *px = p_.x.data(), *py = p_.y.data();
  const double* pz = p_.z.data();
  double* bound = bound_.data();
  const std::uint8_t* st = state_.data();
  const FrictionLaw law = law_;
  if (!state.settled) {
    double change = 0.0, total = 0.0;
#pragma omp parallel for reduction(+ : change, total) schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
      const double b = law.max_tangential(pz[k]);
      change += std::abs(b - bound[k]);
      total += b;
    }
    sum(change, total);
    change = total > 0.0 ? change / total : 0.0;
    // A subproblem whose bound cannot carry the load while the law's can
    // is not a solution of the law: move on to the law's bound.
    const bool short_of_load = overloaded_ && q0 <= total / nn * (1.0 + 1e-9);
    if (change > tolerance || short_of_load) {
      if (change < 0.5 * state.best_change) {
        state.best_change = change;
        state.stalled = 0;
      } else if (++state.stalled >= kStalledUpdates && !short_of_load) {
        // The bound cycles (Tresca with ν < 0.5: edge points that gain
        // σ_m,T on entering the contact lift their neighbours off, see
        // the header): keep the last one and solve it to the tolerance.
        state.settled = true;
      }
      if (!state.settled) {
        std::vector<double> next(n);
#pragma omp parallel for schedule(static)
        for (std::size_t k = 0; k < n; ++k) next[k] = law.max_tangential(pz[k]);
        const bool mixed = accelerate_bound(next, change, state);
#pragma omp parallel for schedule(static)
        for (std::size_t k = 0; k < n; ++k) {
          const double b = next[k];
          if (st[k] == kSlip && bound[k] > 0.0) {  // sliding points stay on the cone
            px[k] *= b / bound[k];
            py[k] *= b / bound[k];
          }
          bound[k] = b;
        }
        state.bound_change = change;
        project_tangential(load.x, load.y, it, true);
        state.conjugate_n = state.conjugate_t = false;
        ++bound_updates_;
        accelerated_updates_ += mixed ? 1 : 0;
        log::debug("{}: iteration {}, bound update {} ({}), change {:.3g}", kSolver, it, bound_updates_,
                   mixed ? "Anderson" : "plain", change);
        return Subproblem::Updated;
      }
    }
  }
  if (!(res.error < tolerance)) return Subproblem::Open;
  double law_capacity = 0.0;
#pragma omp parallel for reduction(+ : law_capacity) schedule(static)
  for (std::size_t k = 0; k < n; ++k) law_capacity += law.max_tangential(pz[k]);
  sum(law_capacity);
  law_capacity /= nn;
  if (overloaded_ && q0 <= law_capacity * (1.0 + 1e-9))
    throw NumericalError(kSolver, it, "mean tangential traction",
                         fmt::format("the last friction bound carries {:g} Pa of the {:g} Pa imposed while the "
                                     "law carries {:g} Pa (its contact edges kept changing)",
                                     capacity_, q0, law_capacity));
  capacity_ = law_capacity;
  if (overloaded_)  // the law's bound cannot carry the load either
    throw InputError(fmt::format(
        "frictional contact: the tangential load ‖⟨p_T⟩‖ = {:g} Pa exceeds what {} friction can carry on "
        "this contact, ⟨p_T,max⟩ = σ_m,T A/A0 = {:g} Pa: the contact slides as a whole (gross sliding); "
        "allowed: ‖⟨p_T⟩‖ ≤ {:g} Pa",
        q0, law_.to_string(), capacity_, capacity_));
  return Subproblem::Solved;
}

// Anderson's mixing, type II (Walker & Ni 2011, Anderson 1965), of the
// fixed point b = G(b), G(b) = law(p_N) of the subproblem solved with bound b:
// with the residuals f_j = G(b_j) − b_j of the last m + 1 updates and their
// differences ΔF, ΔG, γ minimises ‖f_k − ΔF γ‖₂ and the next bound is
// G(b_k) − ΔG γ. Safeguards: a change that did not shrink restarts the
// history (plain update); a mixed bound < 0 on the contact is not taken.
bool FrictionalContact::accelerate_bound(std::vector<double>& next, double change, Iterate& state) {
  if (acceleration_ != OuterAcceleration::Anderson) return false;
  const std::size_t n = h_.size();
  const double *bound = bound_.data(), *pz = p_.z.data();
  if (!(change < state.last_change)) {
    plain_history_.clear();
    residual_history_.clear();
  }
  state.last_change = change;
  std::vector<double> f(n);
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < n; ++k) f[k] = next[k] - bound[k];
  plain_history_.push_back(next);
  residual_history_.push_back(std::move(f));
  if (plain_history_.size() > static_cast<std::size_t>(memory_) + 1) {
    plain_history_.erase(plain_history_.begin());
    residual_history_.erase(residual_history_.begin());
  }
  const std::size_t m = plain_history_.size() - 1;
  if (m == 0) return false;
  // Normal equations ΔFᵀΔF γ = ΔFᵀ f_k (m ≤ 8 columns).
  std::vector<double> sums(m * m + m, 0.0);
  const std::vector<double>& fk = residual_history_[m];
  std::vector<double> df(m);
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t i = 0; i < m; ++i) df[i] = residual_history_[i + 1][k] - residual_history_[i][k];
    for (std::size_t i = 0; i < m; ++i) {
      for (std::size_t j = 0; j <= i; ++j) sums[i * m + j] += df[i] * df[j];
      sums[m * m + i] += df[i] * fk[k];
    }
  }
  body_->sum(sums);
  std::vector<double> a(m * m), gamma(sums.begin() + static_cast<std::ptrdiff_t>(m * m), sums.end());
  double trace = 0.0;
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = 0; j <= i; ++j) a[i * m + j] = a[j * m + i] = sums[i * m + j];
    trace += a[i * m + i];
  }
  if (!(trace > 0.0)) return false;
  for (std::size_t i = 0; i < m; ++i) a[i * m + i] += 1e-12 * trace;  // a tiny Tikhonov term for near-parallel columns
  for (std::size_t i = 0; i < m; ++i) {  // Cholesky, a = L Lᵀ in the lower triangle
    for (std::size_t j = 0; j <= i; ++j) {
      double v = a[i * m + j];
      for (std::size_t l = 0; l < j; ++l) v -= a[i * m + l] * a[j * m + l];
      if (i == j) {
        if (!(v > 0.0)) return false;
        a[i * m + i] = std::sqrt(v);
      } else {
        a[i * m + j] = v / a[j * m + j];
      }
    }
  }
  for (std::size_t i = 0; i < m; ++i) {  // L y = rhs, Lᵀ γ = y
    for (std::size_t l = 0; l < i; ++l) gamma[i] -= a[i * m + l] * gamma[l];
    gamma[i] /= a[i * m + i];
  }
  for (std::size_t i = m; i-- > 0;) {
    for (std::size_t l = i + 1; l < m; ++l) gamma[i] -= a[l * m + i] * gamma[l];
    gamma[i] /= a[i * m + i];
  }
  for (double g : gamma)
    if (!std::isfinite(g)) return false;
  std::vector<double> mixed(n);
  double negative = 0.0;
#pragma omp parallel for reduction(+ : negative) schedule(static)
  for (std::size_t k = 0; k < n; ++k) {
    double b = next[k];
    for (std::size_t i = 0; i < m; ++i) b -= gamma[i] * (plain_history_[i + 1][k] - plain_history_[i][k]);
    mixed[k] = pz[k] > 0.0 ? b : 0.0;  // no friction out of contact
    negative += pz[k] > 0.0 && b < 0.0 ? 1.0 : 0.0;
  }
  sum(negative);
  if (negative > 0.0) return false;  // out of the admissible set: the plain update
  next.swap(mixed);
  return true;
}

// The normal direction t_N = d_N + β t_N,old on the contact, shifted to zero
// sum; returns Σ ∂J/∂p_N t_N (Algorithm 1, line 13).
double FrictionalContact::normal_direction(double beta, double n_c) {
  const std::size_t n = h_.size();
  double* tz = t_.z.data();
  const double *tz_old = t_old_.z.data(), *dz = d_.z.data();
  const std::uint8_t* state = state_.data();
  double sum = 0.0;
#pragma omp parallel for reduction(+ : sum) schedule(static)
  for (std::size_t k = 0; k < n; ++k) {
    tz[k] = state[k] == kOpen ? 0.0 : dz[k] + beta * tz_old[k];
    sum += tz[k];
  }
  this->sum(sum);
  const double shift = sum / n_c;
  double slope = 0.0;
#pragma omp parallel for reduction(+ : slope) schedule(static)
  for (std::size_t k = 0; k < n; ++k) {
    if (state[k] == kOpen) continue;
    tz[k] -= shift;
    slope += dz[k] * tz[k];
  }
  this->sum(slope);
  return slope;
}

// The tangential direction: free (stick, released) points move along
// d_T + β t_T,old, shifted to zero sum; sliding points only turn on the cone.
// Returns Σ ∂J/∂p_T·t_T and sets the turn's curvature.
double FrictionalContact::tangential_direction(double beta, const GapShifts& shifts, double& turn_curvature) {
  const std::size_t n = h_.size();
  double *tx = t_.x.data(), *ty = t_.y.data();
  const double *tx_old = t_old_.x.data(), *ty_old = t_old_.y.data(), *dx = d_.x.data(), *dy = d_.y.data();
  const double *px = p_.x.data(), *py = p_.y.data(), *ux = u_.x.data(), *uy = u_.y.data();
  const std::uint8_t* state = state_.data();
  const bool sliding = all_sliding_;
  const double sx = shifts.x, sy = shifts.y;
  double sum_x = 0.0, sum_y = 0.0, n_free = 0.0;
#pragma omp parallel for reduction(+ : sum_x, sum_y, n_free) schedule(static)
  for (std::size_t k = 0; k < n; ++k) {
    double ax = 0.0, ay = 0.0;
    if (state[k] == kStick || state[k] == kReleased) {
      ax = dx[k] + beta * tx_old[k];
      ay = dy[k] + beta * ty_old[k];
      n_free += 1.0;
    } else if (state[k] == kSlip && !sliding) {
      const double r = norm(px[k], py[k]);
      if (r > 0.0) {  // keep the turn only
        const double nx = px[k] / r, ny = py[k] / r;
        ax = dx[k] + beta * tx_old[k];
        ay = dy[k] + beta * ty_old[k];
        const double along = ax * nx + ay * ny;
        ax -= along * nx;
        ay -= along * ny;
      }
    }
    tx[k] = ax;
    ty[k] = ay;
    sum_x += ax;
    sum_y += ay;
  }
  sum(sum_x, sum_y, n_free);
  const bool shift = n_free > 0.0 && !sliding;
  const double cx = shift ? sum_x / n_free : 0.0, cy = shift ? sum_y / n_free : 0.0;
  double slope = 0.0, curvature = 0.0;
#pragma omp parallel for reduction(+ : slope, curvature) schedule(static)
  for (std::size_t k = 0; k < n; ++k) {
    const double gx = ux[k] - sx, gy = uy[k] - sy;
    if (state[k] == kStick || state[k] == kReleased) {
      tx[k] -= cx;
      ty[k] -= cy;
    } else if (state[k] == kSlip && (tx[k] != 0.0 || ty[k] != 0.0)) {
      // Turning on the circle ‖p_T‖ = p_T,max adds the curvature of the
      // constraint, its multiplier ‖g_T‖/p_T,max, to the model's t·Ft.
      const double r = norm(px[k], py[k]);
      const double speed = std::max(-(gx * px[k] + gy * py[k]) / r, 0.0);
      curvature += speed / r * (tx[k] * tx[k] + ty[k] * ty[k]);
    }
    if (state[k] != kOpen) slope += gx * tx[k] + gy * ty[k];
  }
  sum(slope, curvature);
  turn_curvature = curvature;
  return slope;
}

// Search directions (Algorithm 1, line 8), one conjugate sequence for the
// normal and one for the tangential traction: t = d + β t_old, with zero
// sum (the imposed means stay imposed); at sliding points p_T only turns.
FrictionalContact::Slopes FrictionalContact::search_directions(const GapShifts& shifts, Iterate& state,
                                                               const Residual& res) {
  std::swap(t_old_, t_);
  // A block whose residual grew (the other one moved it through the
  // coupling) restarts from its gradient.
  const double beta_n =
      state.conjugate_n && state.rn_old > 0.0 && res.rn < kBetaMax * state.rn_old ? res.rn / state.rn_old : 0.0;
  const double beta_t =
      state.conjugate_t && state.rt_old > 0.0 && res.rt < kBetaMax * state.rt_old ? res.rt / state.rt_old : 0.0;
  Slopes s;
  s.normal = normal_direction(beta_n, shifts.contact_points);
  if (!(s.normal > 0.0) && beta_n != 0.0) s.normal = normal_direction(0.0, shifts.contact_points);  // not descent: restart
  s.tangential = tangential_direction(beta_t, shifts, s.turn_curvature);
  if (!(s.tangential > 0.0) && beta_t != 0.0) s.tangential = tangential_direction(0.0, shifts, s.turn_curvature);
  if (!(s.normal > 0.0)) s.normal = 0.0;  // no descent along this block: no step on it
  if (!(s.tangential > 0.0)) s.tangential = 0.0;
  state.rn_old = res.rn;
  state.rt_old = res.rt;
  return s;
}

// Step lengths: the minimum of the quadratic model along τ_N t_N + τ_T t_T,
//   [t_N·Ft_N  t_N·Ft_T] [τ_N]   [Σ ∂J/∂p_N t_N]
//   [t_T·Ft_N  t_T·Ft_T] [τ_T] = [Σ ∂J/∂p_T·t_T],
// the forms by Parseval from the spectra of t (decoupled for ν = 0.5).
std::pair<double, double> FrictionalContact::step_lengths(const Slopes& slopes, int it) {
  HalfSpace::BlockForm form = body_->block_form(t_);
  form.tt += slopes.turn_curvature;
  const double slope_n = slopes.normal, slope_t = slopes.tangential;
  double tau_n = 0.0, tau_t = 0.0;
  const double det = form.nn * form.tt - form.nt * form.nt;
  if (form.tt > 0.0 && form.nn > 0.0 && det > 1e-14 * form.nn * form.tt) {
    tau_n = (form.tt * slope_n - form.nt * slope_t) / det;
    tau_t = (form.nn * slope_t - form.nt * slope_n) / det;
    if (tau_n < 0.0 || tau_t < 0.0)  // the coupling would reverse one: one step along t (line 13)
      tau_n = tau_t = (slope_n + slope_t) / (form.nn + 2.0 * form.nt + form.tt);
  } else if (form.nn > 0.0) {
    tau_n = slope_n / form.nn;
  } else if (form.tt > 0.0) {
    tau_t = slope_t / form.tt;
  } else if (slope_n == 0.0) {
    // No descent direction (a contact of one point) while points outside
    // still penetrate: admit them with a cell's own stiffness.
    tau_n = 1.0 / body_->self_compliance();
  }
  if (!std::isfinite(tau_n) || !std::isfinite(tau_t) || tau_n < 0.0 || tau_t < 0.0)
    throw NumericalError(kSolver, it, "step length",
                         fmt::format("τ_N = {}, τ_T = {} (t·Ft: NN {}, TT {}, NT {})", tau_n, tau_t, form.nn,
                                     form.tt, form.nt));
  return {tau_n, tau_t};
}

// Descend (line 14): p_N ≥ 0 and re-admit penetrating points (Polonsky–
// Keer); sliding points stay on the cone, turning towards −g_T. Then p_N
// rescaled to its mean (A.8c) and p_T into the friction cone with its mean (line 15).
void FrictionalContact::descend(double tau_n, double tau_t, const MeanTraction& load, int it, Iterate& st) {
  const std::size_t n = h_.size();
  const double nn = points();
  double *px = p_.x.data(), *py = p_.y.data(), *pz = p_.z.data(), *bound = bound_.data();
  const double *ux = u_.x.data(), *uy = u_.y.data(), *uz = u_.z.data(), *h = h_.data();
  const double *tx = t_.x.data(), *ty = t_.y.data(), *tz = t_.z.data();
  const std::uint8_t* state = state_.data();
  const double sn = shift_n_, sx = shift_x_, sy = shift_y_;
  double overlap = 0.0, new_sum = 0.0;
#pragma omp parallel for reduction(+ : overlap, new_sum) schedule(static)
  for (std::size_t k = 0; k < n; ++k) {
    if (state[k] == kOpen) {
      const double gn = uz[k] - h[k] - sn;
      const bool readmit = gn < 0.0;
      pz[k] = readmit ? -tau_n * gn : 0.0;
      px[k] = py[k] = 0.0;
      overlap += readmit ? 1.0 : 0.0;
      new_sum += pz[k];
      continue;
    }
    pz[k] = std::max(pz[k] - tau_n * tz[k], 0.0);
    if (pz[k] == 0.0) bound[k] = 0.0;  // friction lost in this subproblem is not regained in it
    double ax = px[k] - tau_t * tx[k], ay = py[k] - tau_t * ty[k];
    const double r0 = norm(px[k], py[k]);
    if (state[k] == kSlip && r0 > 0.0) {
      // The outward push of the slip, taken out again by the projection
      // below, keeps the turn towards −g_T: small where the point slides fast.
      const double nx = px[k] / r0, ny = py[k] / r0;
      const double along = (ux[k] - sx) * nx + (uy[k] - sy) * ny;
      ax -= tau_t * along * nx;
      ay -= tau_t * along * ny;
    }
    const double b = pz[k] > 0.0 ? bound[k] : 0.0, r = norm(ax, ay);
    const double s = !(b > 0.0) ? 0.0 : (state[k] == kSlip && r > 0.0 ? b / r : 1.0);
    px[k] = s * ax;
    py[k] = s * ay;
    new_sum += pz[k];
  }
  sum(overlap, new_sum);
  if (!(new_sum > 0.0)) throw NumericalError(kSolver, it, "normal traction", "all pressures vanished");
  const double alpha = load.normal * nn / new_sum;  // impose ⟨p_N⟩ = p_N,0   (A.8c)
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < n; ++k) pz[k] *= alpha;
  project_tangential(load.x, load.y, it, true);
  st.conjugate_n = overlap == 0.0;
  st.conjugate_t = overlap == 0.0;  // releases do not restart it (as points leaving the contact in PK)
}

FrictionalResult FrictionalContact::solve(const MeanTraction& load, const FrictionalOptions& opt) {
  check_load(load);
  if (!(opt.tolerance > 0.0 && opt.tolerance <= FrictionalOptions::max_tolerance))
    throw InputError(fmt::format("frictional contact: tolerance = {:g}; allowed: (0, {:g}] (a larger one lets a "
                                 "solve stop before it has an answer)",
                                 opt.tolerance, FrictionalOptions::max_tolerance));
  if (!(opt.anderson_memory >= 1 && opt.anderson_memory <= FrictionalOptions::max_anderson_memory))
    throw InputError(fmt::format("frictional contact: anderson_memory = {}; allowed: [1, {}]", opt.anderson_memory,
                                 FrictionalOptions::max_anderson_memory));
  tolerance_ = opt.tolerance;
  history_.clear();
  bound_updates_ = accelerated_updates_ = 0;
  acceleration_ = opt.outer_acceleration;
  memory_ = opt.anderson_memory;
  plain_history_.clear();
  residual_history_.clear();
  if (load.normal == 0.0) {
    reset();
    for (RealField* f : {&u_.x, &u_.y, &u_.z}) f->fill(0.0);
    std::fill(state_.begin(), state_.end(), kOpen);
    shift_n_ = -h_max_;
    shift_x_ = shift_y_ = 0.0;
    all_sliding_ = false;
    return finish(0, 0.0, 0.0, 0.0, load);
  }
  warm_start(load);
  Iterate state;
  for (int it = 0; it < opt.max_iterations; ++it) {
    body_->vector_displacement(p_, u_);  // u = F * p   (Algorithm 1, line 5)
    const GapShifts shifts = measure_shifts(it, opt.stop && opt.stop());
    if (shifts.stick_zone_lost) {
      restart_tangential(load, it, state);
      continue;
    }
    shift_n_ = shifts.normal;
    shift_x_ = shifts.x;
    shift_y_ = shifts.y;
    const Residual res = gradient(shifts);
    if (!std::isfinite(res.error)) throw NumericalError(kSolver, it, "cost (A.14)", "not finite (NaN in u or p)");
    if (it == 0) state.first_error = res.error;
    if (it % 10 == 0)  // long solves: -v
      log::debug("{}: iteration {}, ε = {:.3g}, {} bound updates", kSolver, it, res.error, bound_updates_);
    history_.push_back(res.error);
    if (history_.size() > kHistory) history_.erase(history_.begin());
    const Subproblem sub = check_subproblem(res, load, it, state);
    if (sub == Subproblem::Solved) return finish(it, res.error, res.error_n, res.error_t, load);
    if (sub == Subproblem::Updated) continue;
    const Slopes slopes = search_directions(shifts, state, res);
    const auto [tau_n, tau_t] = step_lengths(slopes, it);
    descend(tau_n, tau_t, load, it, state);
  }
  throw NumericalError(kSolver, opt.max_iterations, "cost (A.14)",
                       fmt::format("no convergence to {:g} in {} iterations (ε = {:.3g} at the first iteration, "
                                   "{} updates of the friction bound); last {} errors: {:.3g}",
                                   opt.tolerance, opt.max_iterations, state.first_error, bound_updates_,
                                   history_.size(), fmt::join(history_, ", ")));
}

FrictionalResult FrictionalContact::finish(int iterations, double error, double error_n, double error_t,
                                           const MeanTraction& load) {
  const std::size_t n = h_.size();
  const double nn = points();
  double sum_x = 0.0, sum_y = 0.0, sum_z = 0.0, contact = 0.0, stick = 0.0, work = 0.0, unsettled = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double pn = p_.z[k];
    const double b = pn > 0.0 ? bound_[k] : 0.0;
    const double law_b = law_.max_tangential(pn);
    unsettled += std::abs(b - law_b) > 1e-6 * std::max(b, law_b) ? 1.0 : 0.0;
    const bool in = pn > 0.0;
    const bool sticks = in && b > 0.0 && norm(p_.x[k], p_.y[k]) < (1.0 - kOnCone) * b;
    gap_[k] = in ? 0.0 : u_.z[k] - h_[k] - shift_n_;
    slip_.x[k] = sticks ? 0.0 : u_.x[k] - shift_x_;
    slip_.y[k] = sticks ? 0.0 : u_.y[k] - shift_y_;
    slip_.z[k] = 0.0;
    map_[k] = static_cast<double>(!in ? ContactState::Open : sticks ? ContactState::Stick : ContactState::Slip);
    sum_x += p_.x[k];
    sum_y += p_.y[k];
    sum_z += pn;
    contact += in ? 1.0 : 0.0;
    stick += sticks ? 1.0 : 0.0;
    work += p_.x[k] * u_.x[k] + p_.y[k] * u_.y[k] + pn * u_.z[k];
  }
  sum(sum_x, sum_y, sum_z, contact, stick, work, unsettled);
  plain_history_.clear();  // Anderson's history is the solve's own
  residual_history_.clear();
  FrictionalResult r;
  r.iterations = iterations;
  r.bound_updates = bound_updates_;
  r.accelerated_updates = accelerated_updates_;
  r.unsettled_points = static_cast<long>(unsettled);
  r.error = error;
  r.normal_error = error_n;
  r.tangential_error = error_t;
  r.mean_traction = {sum_z / nn, sum_x / nn, sum_y / nn};
  r.contact_fraction = contact / nn;
  r.stick_fraction = stick / nn;
  r.slip_fraction = (contact - stick) / nn;
  r.full_sliding = load.normal > 0.0 && contact > 0.0 && stick == 0.0 && norm(load.x, load.y) > 0.0;
  r.interference = h_max_ + shift_n_;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  r.tangential_displacement_x = r.full_sliding ? nan : shift_x_;
  r.tangential_displacement_y = r.full_sliding ? nan : shift_y_;
  r.elastic_energy = 0.5 * work * grid().cell_area();
  r.frictional_force_ratio = r.mean_traction.normal > 0.0
                                 ? norm(r.mean_traction.x, r.mean_traction.y) / r.mean_traction.normal
                                 : 0.0;
  return r;
}

}  // namespace wearscale::bem
