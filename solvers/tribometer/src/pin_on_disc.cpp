#include "wearscale/tribometer/pin_on_disc.hpp"

#include "wearscale/tribometer/state_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "stage_compliance.hpp"
#include "track_stage_compliance.hpp"
#include "wear_share.hpp"
#include "wearscale/core/errors.hpp"

namespace wearscale::tribometer {

namespace {
constexpr const char* kModel = kPinOnDiscModel;

void require(bool ok, const char* key, double value, const char* allowed) {
  if (!ok) throw InputError(fmt::format("pin-on-disc: {} = {:g} is not allowed; allowed: {}", key, value, allowed));
}

// ∫_{−∞}^{t} max(0, 1 − |u|) du: the overlap, integrated over the slide, of
// a pin row with a strip cell (both one cell long) whose offset is u.
double hat_integral(double t) {
  if (t <= -1.0) return 0.0;
  if (t <= 0.0) return 0.5 * (t + 1.0) * (t + 1.0);
  if (t <= 1.0) return 1.0 - 0.5 * (1.0 - t) * (1.0 - t);
  return 1.0;
}
}  // namespace


void PinOnDiscSetup::validate() const {
  require(grid >= 8 && grid <= 4096, "grid", static_cast<double>(grid), "8 to 4096 cells");
  require(size > 0.0 && std::isfinite(size), "size", size, "> 0 m");
  require(pin_radius > size / std::sqrt(2.0), "pin_radius", pin_radius, "> size/√2 (the sphere must cover the window)");
  require(normal_load > 0.0 && std::isfinite(normal_load), "normal_load", normal_load, "> 0 N");
  require(velocity > 0.0 && std::isfinite(velocity), "velocity", velocity, "> 0 m/s");
  require(path_length >= size && std::isfinite(path_length), "path_length", path_length,
          "≥ size (the window is part of the path)");
  require(time_step > 0.0 && std::isfinite(time_step), "time_step", time_step, "> 0 s");
  require(distance > 0.0 && std::isfinite(distance), "distance", distance, "> 0 m");
  require(velocity * time_step <= distance * (1.0 + 1e-12), "time_step", time_step,
          "≤ distance/velocity (at least one step: a longer step would overshoot the distance)");
  require(layer_thickness >= 0.0, "layer_thickness", layer_thickness, "≥ 0 m or inf");
  require(e_star > 0.0 && std::isfinite(e_star), "e_star", e_star, "> 0 Pa");
  require(nonplanar_slope >= 0.0 && nonplanar_slope < 0.2, "nonplanarity.slope", nonplanar_slope, "[0, 0.2)");
  require(nonplanar_period > 0.0 && std::isfinite(nonplanar_period), "nonplanarity.period", nonplanar_period, "> 0 m");
  require(tolerance > 0.0 && tolerance < 1e-3, "tolerance", tolerance, "(0, 1e-3)");
  require(stage_tolerance > 0.0 && stage_tolerance < 1e-3, "stage_tolerance", stage_tolerance, "(0, 1e-3)");
  require(max_iterations >= 1, "max_iterations", max_iterations, "≥ 1");
  if (track == Track::Resolved)
    require(static_cast<double>(grid) * path_length / size <= 1e6, "path_length", path_length,
            "at most 10⁶ track cells along the circumference (resolved track)");
  if (!pin_roughness.empty() && pin_roughness.size() != grid * grid)
    throw InputError(fmt::format("pin-on-disc: the pin's roughness has {} heights; allowed: grid² = {}",
                                 pin_roughness.size(), grid * grid));
  if (!disc_roughness.empty()) {
    if (track != Track::Resolved)
      throw InputError("pin-on-disc: a rough disc needs track = \"resolved\": the averaged track's disc is one "
                       "height per x column, invariant along the sliding direction, and holds no roughness along it");
    if (disc_roughness.size() != grid * track_cells())
      throw InputError(fmt::format("pin-on-disc: the disc's roughness has {} heights; allowed: grid × track cells "
                                   "= {} × {}",
                                   disc_roughness.size(), grid, track_cells()));
  }
  for (const auto* heights : {&pin_roughness, &disc_roughness})
    for (const double v : *heights)
      if (!std::isfinite(v)) throw InputError(fmt::format("pin-on-disc: a roughness height is {}; allowed: finite", v));
}

void PinOnDiscSetup::validate_laws() const {
  for (const auto* law : {&on_layer, &on_substrate})
    if (!(law->p_crit > 0.0) || !(law->mu0 >= 0.0) || law->pair.find('/') == std::string::npos)
      throw InputError(fmt::format("pin-on-disc: the interface law '{}' is incomplete (p_crit = {:g}, μ0 = {:g})",
                                   law->pair, law->p_crit, law->mu0));
}

std::size_t PinOnDiscSetup::track_cells() const {
  const double cells = std::round(path_length / (size / static_cast<double>(grid)));
  return std::max(grid, static_cast<std::size_t>(cells));
}

double PinOnDiscSetup::tilt_period() const {
  return track == Track::Resolved ? static_cast<double>(track_cells()) * size / static_cast<double>(grid)
                                  : nonplanar_period;
}

double PinOnDiscSetup::explicit_step() const {
  const double step = velocity * time_step;
  return step_bounded() ? size / static_cast<double>(grid) : step;
}

bool PinOnDiscSetup::step_bounded() const {
  return track == Track::Resolved && velocity * time_step > size / static_cast<double>(grid);
}

PinOnDisc::~PinOnDisc() = default;

PinOnDisc::PinOnDisc(const PinOnDiscSetup& setup)
    : setup_((setup.validate(), setup.validate_laws(), setup)), pin_(Grid2D::square(setup.grid, setup.size)),
      profile_(pin_.grid()), contact_(RealField(pin_.grid()), setup.e_star, setup.boundary),
      pin_rate_(pin_.grid().size()), layer_(pin_.grid().size(), 0) {
  const Grid2D& g = pin_.grid();
  track_ = setup.track == Track::Resolved ? setup.track_cells() : 0;
  disc_.assign(track_ > 0 ? g.nx * track_ : g.nx, 0.0);
  disc_rate_.assign(track_ > 0 ? g.size() : g.nx, 0.0);
  const double r2max = setup.pin_radius * setup.pin_radius;
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) {
      const double x = g.x(i) - 0.5 * g.lx, y = g.y(j) - 0.5 * g.ly;
      pin_(i, j) = setup.pin_radius - std::sqrt(r2max - x * x - y * y);  // spherical pin, summit at the centre
    }
  // The initial roughness on the unworn surfaces (z_pin is measured into the pin: a
  // rough height h sticks out of the pin by h, so it is subtracted).
  if (!setup.pin_roughness.empty())
    for (std::size_t k = 0; k < pin_.size(); ++k) pin_[k] -= setup.pin_roughness[k];
  if (!setup.disc_roughness.empty()) disc_ = disc0_ = setup.disc_roughness;
  if (setup.measure_roughness) pin0_.assign(pin_.begin(), pin_.end());
}


double PinOnDisc::disc_height(const double* disc, std::size_t i, std::size_t j, double s) const {
  if (track_ == 0) return disc[i];
  // The strip under window row j at s: linear between its two nearest cells.
  const double at = static_cast<double>(j) + s / grid().dx();
  const double base = std::floor(at), f = at - base;
  const auto m = static_cast<std::size_t>(std::fmod(base, static_cast<double>(track_)));
  const double* row = disc + i * track_;
  return (1.0 - f) * row[m] + f * row[(m + 1) % track_];
}

void PinOnDisc::build_profile(double s) {
  const Grid2D& g = grid();
  const double theta = 2.0 * std::numbers::pi * s / setup_.tilt_period();
  const double tx = setup_.nonplanar_slope * std::cos(theta), ty = setup_.nonplanar_slope * std::sin(theta);
  for (std::size_t i = 0; i < g.nx; ++i) {
    const double x = g.x(i) - 0.5 * g.lx;
    for (std::size_t j = 0; j < g.ny; ++j) {
      const double y = g.y(j) - 0.5 * g.ly;
      profile_(i, j) = disc_height(disc_.data(), i, j, s) + tx * x + ty * y - pin_(i, j);  // h = z_disc − z_pin
    }
  }
}

void PinOnDisc::classify(double s, const double* disc, std::vector<char>& layer) const {
  const Grid2D& g = grid();
  const double h = setup_.layer_thickness;
  const bool tilted = setup_.tilt_in_layer_test();
  const double theta = 2.0 * std::numbers::pi * s / setup_.tilt_period();
  const double tx = tilted ? setup_.nonplanar_slope * std::cos(theta) : 0.0;
  const double ty = tilted ? setup_.nonplanar_slope * std::sin(theta) : 0.0;
  layer.resize(g.size());
  for (std::size_t i = 0; i < g.nx; ++i) {
    const double x = g.x(i) - 0.5 * g.lx;
    for (std::size_t j = 0; j < g.ny; ++j) {
      const double y = g.y(j) - 0.5 * g.ly;
      // Worn depth (with the tilt if "tilted"), from the initial height of a rough disc (its oxide follows it).
      const double depth = disc0_.empty() ? -(disc_height(disc, i, j, s) + tx * x + ty * y)
                                          : disc_height(disc0_.data(), i, j, s) - (disc_height(disc, i, j, s) + tx * x + ty * y);
      layer[g.index(i, j)] = h > 0.0 && depth < h;  // still inside the oxide
    }
  }
}

std::vector<char> PinOnDisc::layer_cells(double s, const double* y) const {
  std::vector<char> out;
  classify(s, y + pin_.size(), out);
  return out;
}

void PinOnDisc::depth_below_layer(const double* y, double* out) const {
  const double* disc = y + pin_.size();
  for (std::size_t i = 0; i < grid().nx; ++i) out[i] = -disc[i] - setup_.layer_thickness;
}

int PinOnDisc::count_grooves(const double* disc) const {
  const double h = setup_.layer_thickness;
  if (!std::isfinite(h)) return 0;
  const Grid2D& g = grid();
  int grooves = 0;
  bool inside = false;
  for (std::size_t i = 0; i < g.nx; ++i) {
    double z = 0.0;
    if (track_ == 0) {
      z = disc[i];
    } else {
      for (std::size_t m = 0; m < track_; ++m) z += disc[i * track_ + m];
      if (!disc0_.empty())
        for (std::size_t m = 0; m < track_; ++m) z -= disc0_[i * track_ + m];
      z /= static_cast<double>(track_);
    }
    const bool through = -z > h;
    grooves += through && !inside;
    inside = through;
  }
  return grooves;
}

bem::ContactResult PinOnDisc::solve_contact(double s, int max_iterations, bem::ContactMethod method,
                                            double tolerance) {
  const Grid2D& g = grid();
  for (std::size_t k = 0; k < profile_.size(); ++k)
    if (!std::isfinite(profile_[k]))
      throw NumericalError(kModel, solves_, "surface heights",
                           fmt::format("{} at cell ({}, {}) at s = {:g} m (pin {})", profile_[k], k / g.ny, k % g.ny,
                                       s, pin_[k]));
  contact_.set_surface(profile_);
  bem::ContactResult r;
  try {
    r = contact_.solve_mean_pressure(setup_.normal_load / g.area(),
                                     {tolerance > 0.0 ? tolerance : setup_.tolerance, max_iterations, method});
  } catch (const NumericalError& e) {
    contact_.set_added_compliance(nullptr);
    throw NumericalError(kModel, solves_, fmt::format("contact at s = {:g} m", s),
                         fmt::format("{} at iteration {}: {}: {}", e.solver(), e.step(), e.quantity(), e.detail()));
  }
  ++solves_;
  iterations_ += r.iterations;
  // The window must hold the whole contact: pressure on its border means the
  // pin (or its worn flat) is wider than the window, and the periodic
  // half-space then sees overlapping copies of it.
  const RealField& pressure = contact_.pressure();
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j)
      if ((i == 0 || j == 0 || i + 1 == g.nx || j + 1 == g.ny) && pressure(i, j) > 0.0)
        throw InputError(fmt::format("pin-on-disc: at s = {:g} m the contact reaches the edge of the window (size = "
                                     "{:g} m, contact fraction {:.3g}); allowed: a window larger than the contact, "
                                     "i.e. a larger size",
                                     s, g.lx, r.contact_fraction));
  return r;
}

// Friction, contact shares and wear rates of the pressure in contact_ on the
// materials in layer_: pin rate per cell, disc rate per column (averaged) or
// per window cell (resolved).
void PinOnDisc::rates(double s, PinOnDiscSample& out, std::vector<double>* pin_rate, std::vector<double>* disc_rate) {
  const Grid2D& g = grid();
  const double share_layer = pin_share(setup_.on_layer), share_substrate = pin_share(setup_.on_substrate);
  const double disc_scale = g.lx / setup_.path_length;  // the disc passes under the pin L/L_path of the time
  const RealField& p = contact_.pressure();
  double traction = 0.0, on_layer = 0.0, on_substrate = 0.0, p_max = 0.0, pin_volume = 0.0, disc_volume = 0.0;
  double contacts_all = 0.0;
  for (std::size_t i = 0; i < g.nx; ++i) {
    double column = 0.0;
    for (std::size_t j = 0; j < g.ny; ++j) {
      const std::size_t k = g.index(i, j);
      const bool layer = layer_[k] != 0;
      const auto& law = layer ? setup_.on_layer : setup_.on_substrate;
      const double share = layer ? share_layer : share_substrate;
      const double pk = p[k];
      double rate = 0.0;
      if (pk > 0.0) {
        traction += law.mu0 * pk;                   // p_T = μ0 p_N (9.12)
        rate = pk / law.p_crit;                     // dh/ds = p_N/p_crit (9.23)
        (layer ? on_layer : on_substrate) += 1.0;
        contacts_all += 1.0;
        p_max = std::max(p_max, pk);
      }
      if (pin_rate) (*pin_rate)[k] = share * rate;  // (9.24), (9.26)
      pin_volume += share * rate;
      disc_volume += (1.0 - share) * rate;
      column += (1.0 - share) * rate;               // (9.25), (9.27)
      if (disc_rate && track_ > 0) (*disc_rate)[k] = (1.0 - share) * rate;
    }
    if (disc_rate && track_ == 0) (*disc_rate)[i] = column / static_cast<double>(g.ny) * disc_scale;  // averaged along y
  }
  const double contacts = on_layer + on_substrate;
  out.distance = s;
  out.friction = traction * g.cell_area() / setup_.normal_load;
  out.contact_fraction = contacts_all / static_cast<double>(g.size());
  out.layer_contact = contacts > 0 ? on_layer / contacts : 0.0;
  out.substrate_contact = contacts > 0 ? on_substrate / contacts : 0.0;
  out.max_pressure = p_max;
  out.pin_wear = pin_wear_;
  out.disc_wear = disc_wear_;
  out.friction_integral = friction_integral_;
  out.grooves = count_grooves(disc_.data());
  last_pin_volume_rate_ = pin_volume * g.cell_area();
  last_disc_volume_rate_ = disc_volume * g.cell_area();
  if (setup_.measure_roughness) measure_roughness(s, out);
  if (!std::isfinite(out.friction) || !std::isfinite(last_pin_volume_rate_) || !std::isfinite(last_disc_volume_rate_))
    throw NumericalError(kModel, solves_, "friction and wear rates",
                         fmt::format("μ = {}, dV_pin/ds = {}, dV_disc/ds = {} at s = {:g} m", out.friction,
                                     last_pin_volume_rate_, last_disc_volume_rate_, s));
}

void PinOnDisc::evaluate(double s, PinOnDiscSample& out, std::vector<double>* pin_rate,
                         std::vector<double>* disc_rate) {
  if (!std::isfinite(s)) throw NumericalError(kModel, solves_, "sliding distance", fmt::format("s = {}", s));
  build_profile(s);
  classify(s, disc_.data(), layer_);
  const auto r = solve_contact(s, setup_.max_iterations);
  rates(s, out, pin_rate, disc_rate);
  out.iterations = r.iterations;
}

// Resolved track: the wear of the window's cells over a slide from s0 to s1
// deposited on the strip cells they passed over: strip cell m receives the
// rate of row j times the overlap of the two cells integrated over the
// slide, Δx [H(j + σ1 − m) − H(j + σ0 − m)] with σ = s/Δx (exact for a
// pressure constant over the step; the depths sum to rate × (s1 − s0)).
void PinOnDisc::deposit_swept(double s0, double s1) {
  const Grid2D& g = grid();
  const double dx = g.dx(), sigma0 = s0 / dx, sigma1 = s1 / dx;
  const double base = std::floor(sigma0);
  const double f0 = sigma0 - base, f1 = sigma1 - base;  // offsets from the strip cell under row 0
  const auto first = static_cast<std::size_t>(std::fmod(base, static_cast<double>(track_)));
  const int reach = static_cast<int>(std::ceil(f1)) + 1;  // strip cells ahead of a row that it touches
  std::vector<double> kernel(static_cast<std::size_t>(reach) + 2);
  for (int k = -1; k <= reach; ++k)  // m = j + first + k
    kernel[static_cast<std::size_t>(k + 1)] = dx * (hat_integral(f1 - k) - hat_integral(f0 - k));
  for (std::size_t i = 0; i < g.nx; ++i) {
    double* row = disc_.data() + i * track_;
    for (std::size_t j = 0; j < g.ny; ++j) {
      const double rate = disc_rate_[g.index(i, j)];
      if (rate == 0.0) continue;
      for (int k = -1; k <= reach; ++k) {
        const auto m = (first + j + track_ + static_cast<std::size_t>(k + static_cast<int>(track_))) % track_;
        row[m] -= rate * kernel[static_cast<std::size_t>(k + 1)];
      }
    }
  }
}

// The strip cells under the window wear at the rate of the cell above them
// (split between the two nearest strip cells as the window reads them).
void PinOnDisc::spread_on_track(double s, double* strip_rate) const {
  const Grid2D& g = grid();
  std::fill(strip_rate, strip_rate + disc_.size(), 0.0);
  const double at0 = s / g.dx(), base = std::floor(at0), f = at0 - base;
  const auto first = static_cast<std::size_t>(std::fmod(base, static_cast<double>(track_)));
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) {
      const std::size_t m = (first + j) % track_;
      const double rate = disc_rate_[g.index(i, j)];
      strip_rate[i * track_ + m] -= (1.0 - f) * rate;
      strip_rate[i * track_ + (m + 1) % track_] -= f * rate;
    }
}

PinOnDiscSample PinOnDisc::step() {
  PinOnDiscSample sample;
  evaluate(s_, sample, &pin_rate_, &disc_rate_);
  double ds = setup_.explicit_step();  // dh = rate · v dt (9.23)
  if (const double rest = setup_.distance - s_; rest > 0.0 && rest < ds * (1.0 - 1e-9)) ds = rest;  // lands on the distance
  for (std::size_t k = 0; k < pin_rate_.size(); ++k) pin_[k] += pin_rate_[k] * ds;
  if (track_ == 0) {
    for (std::size_t i = 0; i < disc_.size(); ++i) disc_[i] -= disc_rate_[i] * ds;
  } else {
    deposit_swept(s_, s_ + ds);
  }
  pin_wear_ += last_pin_volume_rate_ * ds;
  disc_wear_ += last_disc_volume_rate_ * ds;
  friction_integral_ += sample.friction * ds;
  s_ += ds;
  ++steps_;
  stage_valid_ = false;
  return sample;
}

long PinOnDisc::total_steps() const {
  const double ds = setup_.explicit_step();
  return static_cast<long>(std::ceil(setup_.distance / ds - 1e-9));
}

void PinOnDisc::run(const std::function<void(const PinOnDiscSample&)>& observe) {
  const long steps = total_steps();
  while (steps_ < steps) {
    const PinOnDiscSample sample = step();
    // Each state computed is held to the bounds a restored one is (restore, state_bounds.hpp).
    if (const std::string problem = state_problem(); !problem.empty())
      throw NumericalError("pin-on-disc", steps_, "state", problem);
    observe(sample);
  }
  PinOnDiscSample last;
  evaluate(s_, last, nullptr, nullptr);
  observe(last);
}

RealField PinOnDisc::disc_under_pin() const {
  RealField out(grid());
  for (std::size_t i = 0; i < grid().nx; ++i)
    for (std::size_t j = 0; j < grid().ny; ++j) out(i, j) = disc_height(disc_.data(), i, j, s_);
  return out;
}

std::vector<double> PinOnDisc::disc_column_means() const {
  if (track_ == 0) return disc_;
  std::vector<double> out(grid().nx, 0.0);
  for (std::size_t i = 0; i < grid().nx; ++i) {
    for (std::size_t m = 0; m < track_; ++m) out[i] += disc_[i * track_ + m];
    out[i] /= static_cast<double>(track_);
  }
  return out;
}

std::vector<double> PinOnDisc::disc_initial_column_means() const {
  std::vector<double> out(grid().nx, 0.0);
  if (disc0_.empty()) return out;
  for (std::size_t i = 0; i < grid().nx; ++i) {
    for (std::size_t m = 0; m < track_; ++m) out[i] += disc0_[i * track_ + m];
    out[i] /= static_cast<double>(track_);
  }
  return out;
}

std::vector<double> roughness_values(const PinOnDiscSample& x) {
  const auto& a = x.pin_roughness;
  const auto& b = x.disc_roughness;
  return {a.sa, a.sq, a.hprime_rms, a.cells, b.sa, b.sq, b.hprime_rms, b.cells};
}

void set_roughness_values(PinOnDiscSample& x, const double* v) {
  x.pin_roughness = {v[0], v[1], v[2], v[3]};
  x.disc_roughness = {v[4], v[5], v[6], v[7]};
}

RegionRoughness residual_roughness(const double* e, const char* in, std::size_t nx, std::size_t ny, double dx,
                                   double dy) {
  RegionRoughness r;
  double n = 0.0, sa = 0.0, sq = 0.0, gx = 0.0, gy = 0.0, cx = 0.0, cy = 0.0;
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < ny; ++j) {
      const std::size_t k = i * ny + j;
      if (!in[k]) continue;
      n += 1.0;
      sa += std::abs(e[k]);
      sq += e[k] * e[k];
      if (i + 1 < nx && in[k + ny]) {
        const double d = (e[k + ny] - e[k]) / dx;
        gx += d * d;
        cx += 1.0;
      }
      if (j + 1 < ny && in[k + 1]) {
        const double d = (e[k + 1] - e[k]) / dy;
        gy += d * d;
        cy += 1.0;
      }
    }
  r.cells = n;
  if (n < 3.0) return r;
  r.sa = sa / n;
  r.sq = std::sqrt(sq / n);
  if (cx > 0.0 || cy > 0.0) r.hprime_rms = std::sqrt((cx > 0.0 ? gx / cx : 0.0) + (cy > 0.0 ? gy / cy : 0.0));
  return r;
}

RegionRoughness region_roughness(const double* h, const char* in, std::size_t nx, std::size_t ny, double dx,
                                 double dy) {
  // The form: the least-squares quadric a + bx + cy + dx² + exy + fy² over the region (coordinates centred
  // and scaled to the region's extent), a plane for fewer than 6 cells, the mean for fewer than 3.
  double n = 0.0, sx = 0.0, sy = 0.0;
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < ny; ++j)
      if (in[i * ny + j]) {
        n += 1.0;
        sx += static_cast<double>(i);
        sy += static_cast<double>(j);
      }
  std::vector<double> e(nx * ny, 0.0);
  if (n < 1.0) return residual_roughness(e.data(), in, nx, ny, dx, dy);
  const double mx = sx / n, my = sy / n;
  double ex = 1.0, ey = 1.0;  // half-extents, in cells
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < ny; ++j)
      if (in[i * ny + j]) {
        ex = std::max(ex, std::abs(static_cast<double>(i) - mx));
        ey = std::max(ey, std::abs(static_cast<double>(j) - my));
      }
  const int terms = n >= 6.0 ? 6 : n >= 3.0 ? 3 : 1;
  const auto basis = [&](std::size_t i, std::size_t j, double* f) {
    const double x = (static_cast<double>(i) - mx) / ex, y = (static_cast<double>(j) - my) / ey;
    f[0] = 1.0;
    f[1] = x;
    f[2] = y;
    f[3] = x * x;
    f[4] = x * y;
    f[5] = y * y;
  };
  double m[6][7] = {};
  double f[6];
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < ny; ++j)
      if (in[i * ny + j]) {
        basis(i, j, f);
        for (int a = 0; a < terms; ++a) {
          for (int b = 0; b < terms; ++b) m[a][b] += f[a] * f[b];
          m[a][6] += f[a] * h[i * ny + j];
        }
      }
  // Gaussian elimination with partial pivoting; a term the region cannot determine (collinear cells) is dropped.
  double c[6] = {};
  bool used[6] = {};
  {
    int row = 0;
    int pivot_col[6] = {};
    for (int col = 0; col < terms && row < terms; ++col) {
      int best = row;
      for (int r = row + 1; r < terms; ++r)
        if (std::abs(m[r][col]) > std::abs(m[best][col])) best = r;
      if (std::abs(m[best][col]) <= 1e-10 * std::max(1.0, std::abs(m[0][0]))) continue;
      for (int k = 0; k < 7; ++k) std::swap(m[row][k], m[best][k]);
      for (int r = 0; r < terms; ++r) {
        if (r == row) continue;
        const double q = m[r][col] / m[row][col];
        for (int k = 0; k < 7; ++k)
          if (k < terms || k == 6) m[r][k] -= q * m[row][k];
      }
      pivot_col[row] = col;
      used[col] = true;
      ++row;
    }
    for (int r = 0; r < row; ++r) c[pivot_col[r]] = m[r][6] / m[r][pivot_col[r]];
  }
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < ny; ++j)
      if (in[i * ny + j]) {
        basis(i, j, f);
        double form = 0.0;
        for (int a = 0; a < terms; ++a)
          if (used[a]) form += c[a] * f[a];
        e[i * ny + j] = h[i * ny + j] - form;
      }
  return residual_roughness(e.data(), in, nx, ny, dx, dy);
}

void PinOnDisc::measure_roughness(double s, PinOnDiscSample& out) const {
  const Grid2D& g = grid();
  const RealField& p = contact_.pressure();
  std::vector<char> in(g.size(), 0);
  bool worn = false;
  for (std::size_t k = 0; k < g.size(); ++k) worn |= (in[k] = pin_[k] > pin0_[k]) != 0;
  if (!worn)
    for (std::size_t k = 0; k < g.size(); ++k) in[k] = p[k] > 0.0;
  // z_pin points into the pin: its heights are −z_pin.
  std::vector<double> h(g.size());
  for (std::size_t k = 0; k < g.size(); ++k) h[k] = -pin_[k];
  out.pin_roughness = region_roughness(h.data(), in.data(), g.nx, g.ny, g.dx(), g.dy());
  out.disc_roughness = {};
  if (track_ == 0) return;
  // The disc's wear track: the columns (x) worn anywhere along the circumference, whole; before any
  // wear, the columns under the contact. Its form is the profile across the track (each column's mean
  // along it, the averaged track's disc); the roughness is what varies along the track about it.
  std::vector<char> band(g.nx, 0);
  worn = false;
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t m = 0; m < track_ && !band[i]; ++m)
      band[i] = disc_[i * track_ + m] < (disc0_.empty() ? 0.0 : disc0_[i * track_ + m]);
  for (const char b : band) worn |= b != 0;
  if (!worn)
    for (std::size_t i = 0; i < g.nx; ++i)
      for (std::size_t j = 0; j < g.ny && !band[i]; ++j) band[i] = p(i, j) > 0.0;
  (void)s;
  std::vector<double> e(disc_.size(), 0.0);
  in.assign(disc_.size(), 0);
  for (std::size_t i = 0; i < g.nx; ++i) {
    if (!band[i]) continue;
    double mean = 0.0;
    for (std::size_t m = 0; m < track_; ++m) mean += disc_[i * track_ + m];
    mean /= static_cast<double>(track_);
    for (std::size_t m = 0; m < track_; ++m) {
      e[i * track_ + m] = disc_[i * track_ + m] - mean;
      in[i * track_ + m] = 1;
    }
  }
  out.disc_roughness = residual_roughness(e.data(), in.data(), g.nx, track_, g.dx(), g.dx());
}

void PinOnDisc::save(CheckpointState& state) const {
  state.put("pin_surface", std::span<const double>(pin_.data(), pin_.size()));
  state.put("disc_profile", disc_);
  state.put("distance", s_);
  state.put("pin_wear", pin_wear_);
  state.put("disc_wear", disc_wear_);
  state.put("friction_integral", friction_integral_);
  state.put("steps", static_cast<double>(steps_));
  state.put("solves", static_cast<double>(solves_));
  state.put("contact_iterations", static_cast<double>(iterations_));
  state.put("contact_pressure", std::span<const double>(contact_.pressure().data(), contact_.pressure().size()));
  state.put("contact_gap_shift", contact_.warm_gap_shift());
  state.put("stage_valid", stage_valid_ ? 1.0 : 0.0);
  if (stage_valid_) {
    const auto& x = stage_sample_;
    state.put("stage_state", stage_state_);
    state.put("stage_rate", stage_rate_);
    state.put("stage_sample", std::vector<double>{stage_s_, x.distance, x.friction, x.friction_integral, x.pin_wear,
                                                  x.disc_wear, x.contact_fraction, x.layer_contact,
                                                  x.substrate_contact, x.max_pressure,
                                                  static_cast<double>(x.iterations), static_cast<double>(x.grooves)});
    if (setup_.measure_roughness) state.put("stage_roughness", roughness_values(x));
  }
}

void PinOnDisc::restore(const CheckpointState& state) {
  const auto& pin = state.array("pin_surface");
  const auto& disc = state.array("disc_profile");
  const auto& p = state.array("contact_pressure");
  if (pin.size() != pin_.size() || disc.size() != disc_.size() || p.size() != pin_.size())
    throw InputError(fmt::format("{}: a pin-on-disc state of {} pin cells, {} disc profile values and {} pressures; "
                                 "the case has {} pin cells ({}×{}) and {} disc profile values",
                                 state.origin, pin.size(), disc.size(), p.size(), pin_.size(), grid().nx, grid().ny,
                                 disc_.size()));
  // A checksum proves the bytes intact, not the state possible: the values pass the bounds a computed state
  // is held to (state_problem) before any is taken, every count before it becomes an integer.
  const auto refuse = [&](const std::string& problem) {
    throw InputError(fmt::format("{}: the pin-on-disc state is no state a run reaches ({}); the checkpoint was "
                                 "changed or written by another program: delete it to start afresh",
                                 state.origin, problem));
  };
  for (const std::string& problem :
       {count_problem("steps", state.scalar("steps"), 0.0, static_cast<double>(total_steps())),
        count_problem("contact solves", state.scalar("solves"), 0.0, 2e9),
        count_problem("stage_valid", state.scalar("stage_valid"), 0.0, 1.0)})
    if (!problem.empty()) refuse(problem);
  if (const std::string problem =
          state_problem(state.scalar("distance"), state.scalar("pin_wear"), state.scalar("disc_wear"),
                        state.scalar("friction_integral"), pin, disc, p, state.scalar("contact_gap_shift"));
      !problem.empty())
    refuse(problem);
  std::copy(pin.begin(), pin.end(), pin_.begin());
  std::copy(disc.begin(), disc.end(), disc_.begin());
  s_ = state.scalar("distance");
  pin_wear_ = state.scalar("pin_wear");
  disc_wear_ = state.scalar("disc_wear");
  friction_integral_ = state.scalar("friction_integral");
  // The run's counters: whole numbers a run can reach, or the state is refused (never a cast of NaN or 1e300).
  const auto count = [&](const char* name, double most) {
    const double v = state.scalar(name);
    if (!(v >= 0.0 && v <= most && v == std::floor(v)))
      throw InputError(fmt::format("{}: the saved {} = {} is not a count a run reaches; allowed: a whole number in [0, {}]",
                                   state.origin, name, v, most));
    return v;
  };
  steps_ = static_cast<long>(count("steps", 1e15));
  solves_ = static_cast<int>(count("solves", 2e9));
  iterations_ = state.has("contact_iterations") ? static_cast<long>(count("contact_iterations", 1e15)) : 0;
  contact_.set_warm_start(p, state.scalar("contact_gap_shift"));
  stage_valid_ = state.scalar("stage_valid") != 0.0;
  if (stage_valid_) {
    stage_state_ = state.array("stage_state");
    stage_rate_ = state.array("stage_rate");
    const auto& x = state.array("stage_sample");
    if (stage_state_.size() != state_size() || stage_rate_.size() != state_size() || x.size() != 12)
      throw InputError(fmt::format("{}: the saved implicit stage does not fit this case", state.origin));
    for (const double v : stage_state_)
      if (!std::isfinite(v)) refuse("a value of the saved implicit stage is NaN or infinite");
    for (const double v : stage_rate_)
      if (!std::isfinite(v)) refuse("a rate of the saved implicit stage is NaN or infinite");
    for (const std::string& problem : {count_problem("stage iterations", x[10], 0.0, 1e9),
                                       count_problem("stage grooves", x[11], 0.0, static_cast<double>(setup_.grid))})
      if (!problem.empty()) refuse(problem);
    stage_s_ = x[0];
    stage_sample_ = {x[1], x[2], x[3], x[4], x[5], x[6], x[7], x[8], x[9], static_cast<int>(x[10]),
                     static_cast<int>(x[11])};
    if (setup_.measure_roughness) {
      if (!state.has("stage_roughness") || state.array("stage_roughness").size() != 8)
        throw InputError(fmt::format("{}: the saved implicit stage has no roughness of a rough run", state.origin));
      set_roughness_values(stage_sample_, state.array("stage_roughness").data());
    }
    if (const std::string problem = sample_problem(stage_sample_, setup_); !problem.empty()) refuse(problem);
    if (!(std::isfinite(stage_s_) && stage_s_ >= 0.0 && stage_s_ <= setup_.distance * (1.0 + 1e-9)))
      refuse(fmt::format("the saved stage's distance {:g} m is outside the run's [0, {:g}] m", stage_s_,
                         setup_.distance));
  }
}

std::string PinOnDisc::state_problem(double s, double pin_wear, double disc_wear, double friction_integral,
                                     std::span<const double> pin, std::span<const double> disc,
                                     std::span<const double> pressure, double gap_shift) const {
  if (!(std::isfinite(s) && s >= 0.0 && s <= setup_.distance * (1.0 + 1e-9)))  // the last step lands on it
    return fmt::format("sliding distance s = {:g} m; allowed: within the run's [0, {:g}] m", s, setup_.distance);
  for (const auto& [name, v] : {std::pair{"pin wear", pin_wear}, std::pair{"disc wear", disc_wear},
                                std::pair{"friction integral", friction_integral}})
    if (!(std::isfinite(v) && v >= 0.0)) return fmt::format("{} = {:g}; allowed: finite and ≥ 0", name, v);
  for (const auto& [name, values] : {std::pair{"pin height", pin}, std::pair{"disc height", disc}})
    for (const double v : values)
      if (!std::isfinite(v)) return fmt::format("a {} is {}; allowed: finite", name, v);
  for (const double v : pressure)
    if (!(std::isfinite(v) && v >= 0.0)) return fmt::format("a contact pressure is {:g} Pa; allowed: finite and ≥ 0", v);
  if (!std::isfinite(gap_shift)) return fmt::format("the contact's gap shift is {}; allowed: finite", gap_shift);
  return {};
}

std::string PinOnDisc::state_problem() const {
  if (const std::string problem =
          count_problem("steps", static_cast<double>(steps_), 0.0, static_cast<double>(total_steps()));
      !problem.empty())
    return problem;
  return state_problem(s_, pin_wear_, disc_wear_, friction_integral_, {pin_.data(), pin_.size()}, disc_,
                       {contact_.pressure().data(), contact_.pressure().size()}, contact_.warm_gap_shift());
}

std::vector<double> PinOnDisc::state() const {
  std::vector<double> y(pin_.begin(), pin_.end());
  y.insert(y.end(), disc_.begin(), disc_.end());
  y.push_back(pin_wear_);
  y.push_back(disc_wear_);
  y.push_back(friction_integral_);
  return y;
}

std::vector<double> PinOnDisc::initial_state() const {
  PinOnDisc fresh(setup_);
  return fresh.state();
}

void PinOnDisc::set_state(const double* y, double s) {
  const std::size_t np = pin_.size(), nd = disc_.size();
  std::copy(y, y + np, pin_.begin());
  std::copy(y + np, y + np + nd, disc_.begin());
  pin_wear_ = y[np + nd];
  disc_wear_ = y[np + nd + 1];
  friction_integral_ = y[np + nd + 2];
  s_ = s;
}

namespace {
// The state an integrator hands back is the stage solution recombined
// (z_pred + z_cor), equal to it to rounding.
bool same_state(const std::vector<double>& z, const double* y) {
  double scale = 0.0, diff = 0.0;
  for (std::size_t k = 0; k < z.size(); ++k) {
    scale = std::max(scale, std::abs(z[k]));
    diff = std::max(diff, std::abs(z[k] - y[k]));
  }
  return diff <= 1e-13 * scale;
}
}  // namespace

void PinOnDisc::derivative(double s, const double* y, double* dyds, PinOnDiscSample& sample) {
  const std::size_t np = pin_.size(), nd = disc_.size();
  if (stage_valid_ && std::abs(s - stage_s_) <= 1e-12 * std::abs(s) && same_state(stage_state_, y)) {
    std::copy(stage_rate_.begin(), stage_rate_.end(), dyds);
    sample = stage_sample_;
    return;
  }
  set_state(y, s);
  evaluate(s, sample, &pin_rate_, &disc_rate_);
  std::copy(pin_rate_.begin(), pin_rate_.end(), dyds);
  if (track_ == 0) {
    for (std::size_t i = 0; i < nd; ++i) dyds[np + i] = -disc_rate_[i];
  } else {
    spread_on_track(s, dyds + np);
  }
  dyds[np + nd] = last_pin_volume_rate_;
  dyds[np + nd + 1] = last_disc_volume_rate_;
  dyds[np + nd + 2] = sample.friction;
  // Kept: an integrator asks again for the rate of a state it has just had.
  stage_state_.assign(y, y + state_size());
  stage_rate_.assign(dyds, dyds + state_size());
  stage_s_ = s;
  stage_sample_ = sample;
  stage_valid_ = true;
}

}  // namespace wearscale::tribometer
