#include "wearscale/tribometer/pin_on_disc.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::tribometer {

namespace {
constexpr const char* kModel = "tribometer/pin-on-disc";

void require(bool ok, const char* key, double value, const char* allowed) {
  if (!ok) throw InputError(fmt::format("pin-on-disc: {} = {:g} is not allowed; allowed: {}", key, value, allowed));
}

// Share of an interface's wear taken by the pin: ½ on a like-on-like
// interface (9.24), else all on the body whose junctions give way (9.26).
double pin_share(const materials::InterfaceLaw& law) {
  const auto slash = law.pair.find('/');
  const std::string pin = law.pair.substr(0, slash), other = law.pair.substr(slash + 1);
  if (pin == other) return 0.5;
  return law.governing == pin ? 1.0 : 0.0;
}
}  // namespace

void PinOnDiscSetup::validate() const {
  require(grid >= 8 && grid <= 4096, "grid", static_cast<double>(grid), "8 to 4096 cells");
  require(size > 0.0 && std::isfinite(size), "size", size, "> 0 m");
  require(pin_radius > size / std::sqrt(2.0), "pin_radius", pin_radius, "> size/√2 (the sphere must cover the window)");
  require(normal_load > 0.0 && std::isfinite(normal_load), "normal_load", normal_load, "> 0 N");
  require(velocity > 0.0 && std::isfinite(velocity), "velocity", velocity, "> 0 m/s");
  require(path_length >= size, "path_length", path_length, "≥ size (the window is part of the path)");
  require(time_step > 0.0 && std::isfinite(time_step), "time_step", time_step, "> 0 s");
  require(distance > 0.0 && std::isfinite(distance), "distance", distance, "> 0 m");
  require(velocity * time_step <= distance * (1.0 + 1e-12), "time_step", time_step,
          "≤ distance/velocity (at least one step: a longer step would overshoot the distance)");
  require(layer_thickness >= 0.0, "layer_thickness", layer_thickness, "≥ 0 m or inf");
  require(e_star > 0.0 && std::isfinite(e_star), "e_star", e_star, "> 0 Pa");
  require(nonplanar_slope >= 0.0 && nonplanar_slope < 0.2, "nonplanarity.slope", nonplanar_slope, "[0, 0.2)");
  require(nonplanar_period > 0.0, "nonplanarity.period", nonplanar_period, "> 0 m");
  require(tolerance > 0.0 && tolerance < 1e-3, "tolerance", tolerance, "(0, 1e-3)");
}

void PinOnDiscSetup::validate_laws() const {
  for (const auto* law : {&on_layer, &on_substrate})
    if (!(law->p_crit > 0.0) || !(law->mu0 >= 0.0) || law->pair.find('/') == std::string::npos)
      throw InputError(fmt::format("pin-on-disc: the interface law '{}' is incomplete (p_crit = {:g}, μ0 = {:g})",
                                   law->pair, law->p_crit, law->mu0));
}

PinOnDisc::PinOnDisc(const PinOnDiscSetup& setup)
    : setup_((setup.validate(), setup.validate_laws(), setup)), pin_(Grid2D::square(setup.grid, setup.size)), profile_(pin_.grid()),
      disc_(setup.grid, 0.0), contact_(RealField(pin_.grid()), setup.e_star, setup.boundary), pin_rate_(pin_.grid().size()),
      disc_rate_(setup.grid) {
  const Grid2D& g = pin_.grid();
  const double r2max = setup.pin_radius * setup.pin_radius;
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) {
      const double x = g.x(i) - 0.5 * g.lx, y = g.y(j) - 0.5 * g.ly;
      pin_(i, j) = setup.pin_radius - std::sqrt(r2max - x * x - y * y);  // spherical pin, summit at the centre
    }
}

void PinOnDisc::build_profile(double s) {
  const Grid2D& g = grid();
  const double theta = 2.0 * std::numbers::pi * s / setup_.nonplanar_period;
  const double tx = setup_.nonplanar_slope * std::cos(theta), ty = setup_.nonplanar_slope * std::sin(theta);
  for (std::size_t i = 0; i < g.nx; ++i) {
    const double x = g.x(i) - 0.5 * g.lx;
    for (std::size_t j = 0; j < g.ny; ++j) {
      const double y = g.y(j) - 0.5 * g.ly;
      profile_(i, j) = disc_[i] + tx * x + ty * y - pin_(i, j);  // h = z_disc − z_pin
    }
  }
}

void PinOnDisc::evaluate(double s, PinOnDiscSample& out, std::vector<double>* pin_rate,
                         std::vector<double>* disc_rate) {
  const Grid2D& g = grid();
  if (!std::isfinite(s)) throw NumericalError(kModel, solves_, "sliding distance", fmt::format("s = {}", s));
  build_profile(s);
  for (std::size_t k = 0; k < profile_.size(); ++k)
    if (!std::isfinite(profile_[k]))
      throw NumericalError(kModel, solves_, "surface heights",
                           fmt::format("{} at cell ({}, {}) at s = {:g} m (pin {}, disc {})", profile_[k], k / g.ny,
                                       k % g.ny, s, pin_[k], disc_[k / g.ny]));
  contact_.set_surface(profile_);
  bem::ContactResult r;
  try {
    r = contact_.solve_mean_pressure(setup_.normal_load / g.area(), {setup_.tolerance, 20000});
  } catch (const NumericalError& e) {
    throw NumericalError(kModel, solves_, fmt::format("contact at s = {:g} m", s),
                         fmt::format("{} at iteration {}: {}: {}", e.solver(), e.step(), e.quantity(), e.detail()));
  }
  ++solves_;
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
  const double share_layer = pin_share(setup_.on_layer), share_substrate = pin_share(setup_.on_substrate);
  const double disc_scale = g.lx / setup_.path_length;  // the disc passes under the pin L/L_path of the time
  const RealField& p = contact_.pressure();
  double traction = 0.0, on_layer = 0.0, on_substrate = 0.0, p_max = 0.0, pin_volume = 0.0, disc_volume = 0.0;
  if (disc_rate) std::fill(disc_rate->begin(), disc_rate->end(), 0.0);
  for (std::size_t i = 0; i < g.nx; ++i) {
    const bool layer = -disc_[i] < setup_.layer_thickness;  // worn depth still inside the oxide
    const auto& law = layer ? setup_.on_layer : setup_.on_substrate;
    const double share = layer ? share_layer : share_substrate;
    double column = 0.0;
    for (std::size_t j = 0; j < g.ny; ++j) {
      const std::size_t k = g.index(i, j);
      const double pk = p[k];
      double rate = 0.0;
      if (pk > 0.0) {
        traction += law.mu0 * pk;                   // p_T = μ0 p_N (9.12)
        rate = pk / law.p_crit;                     // dh/ds = p_N/p_crit (9.23)
        (layer ? on_layer : on_substrate) += 1.0;
        p_max = std::max(p_max, pk);
      }
      if (pin_rate) (*pin_rate)[k] = share * rate;  // (9.24), (9.26)
      pin_volume += share * rate;
      disc_volume += (1.0 - share) * rate;
      column += (1.0 - share) * rate;               // (9.25), (9.27)
    }
    if (disc_rate) (*disc_rate)[i] = column / static_cast<double>(g.ny) * disc_scale;  // averaged along y
  }
  const double contacts = on_layer + on_substrate;
  out.distance = s;
  out.friction = traction * g.cell_area() / setup_.normal_load;
  out.contact_fraction = r.contact_fraction;
  out.layer_contact = contacts > 0 ? on_layer / contacts : 0.0;
  out.substrate_contact = contacts > 0 ? on_substrate / contacts : 0.0;
  out.max_pressure = p_max;
  out.iterations = r.iterations;
  out.pin_wear = pin_wear_;
  out.disc_wear = disc_wear_;
  last_pin_volume_rate_ = pin_volume * g.cell_area();
  last_disc_volume_rate_ = disc_volume * g.cell_area();
  if (!std::isfinite(out.friction) || !std::isfinite(last_pin_volume_rate_) || !std::isfinite(last_disc_volume_rate_))
    throw NumericalError(kModel, solves_, "friction and wear rates",
                         fmt::format("μ = {}, dV_pin/ds = {}, dV_disc/ds = {} at s = {:g} m", out.friction,
                                     last_pin_volume_rate_, last_disc_volume_rate_, s));
}

PinOnDiscSample PinOnDisc::step() {
  PinOnDiscSample sample;
  evaluate(s_, sample, &pin_rate_, &disc_rate_);
  double ds = setup_.velocity * setup_.time_step;  // dh = rate · v dt (9.23)
  if (const double rest = setup_.distance - s_; rest > 0.0 && rest < ds * (1.0 - 1e-9)) ds = rest;  // lands on the distance
  for (std::size_t k = 0; k < pin_rate_.size(); ++k) pin_[k] += pin_rate_[k] * ds;
  for (std::size_t i = 0; i < disc_.size(); ++i) disc_[i] -= disc_rate_[i] * ds;
  pin_wear_ += last_pin_volume_rate_ * ds;
  disc_wear_ += last_disc_volume_rate_ * ds;
  s_ += ds;
  ++steps_;
  return sample;
}

long PinOnDisc::total_steps() const {
  const double ds = setup_.velocity * setup_.time_step;
  return static_cast<long>(std::ceil(setup_.distance / ds - 1e-9));
}

void PinOnDisc::run(const std::function<void(const PinOnDiscSample&)>& observe) {
  const long steps = total_steps();
  while (steps_ < steps) observe(step());
  PinOnDiscSample last;
  evaluate(s_, last, nullptr, nullptr);
  observe(last);
}

void PinOnDisc::save(CheckpointState& state) const {
  state.put("pin_surface", std::span<const double>(pin_.data(), pin_.size()));
  state.put("disc_profile", disc_);
  state.put("distance", s_);
  state.put("pin_wear", pin_wear_);
  state.put("disc_wear", disc_wear_);
  state.put("steps", static_cast<double>(steps_));
  state.put("solves", static_cast<double>(solves_));
  state.put("contact_pressure", std::span<const double>(contact_.pressure().data(), contact_.pressure().size()));
  state.put("contact_gap_shift", contact_.warm_gap_shift());
}

void PinOnDisc::restore(const CheckpointState& state) {
  const auto& pin = state.array("pin_surface");
  const auto& disc = state.array("disc_profile");
  const auto& p = state.array("contact_pressure");
  if (pin.size() != pin_.size() || disc.size() != disc_.size() || p.size() != pin_.size())
    throw InputError(fmt::format("{}: a pin-on-disc state of {} pin cells, {} disc columns and {} pressures; the case "
                                 "has {} pin cells ({}×{}) and {} disc columns",
                                 state.origin, pin.size(), disc.size(), p.size(), pin_.size(), grid().nx, grid().ny,
                                 disc_.size()));
  for (const auto* v : {&pin, &disc})
    for (double x : *v)
      if (!std::isfinite(x)) throw InputError(fmt::format("{}: a saved surface height is NaN or infinite", state.origin));
  std::copy(pin.begin(), pin.end(), pin_.begin());
  std::copy(disc.begin(), disc.end(), disc_.begin());
  s_ = state.scalar("distance");
  pin_wear_ = state.scalar("pin_wear");
  disc_wear_ = state.scalar("disc_wear");
  steps_ = static_cast<long>(state.scalar("steps"));
  solves_ = static_cast<int>(state.scalar("solves"));
  contact_.set_warm_start(p, state.scalar("contact_gap_shift"));
}

std::vector<double> PinOnDisc::state() const {
  std::vector<double> y(pin_.begin(), pin_.end());
  y.insert(y.end(), disc_.begin(), disc_.end());
  y.push_back(pin_wear_);
  y.push_back(disc_wear_);
  return y;
}

void PinOnDisc::set_state(const double* y, double s) {
  std::copy(y, y + pin_.size(), pin_.begin());
  std::copy(y + pin_.size(), y + pin_.size() + disc_.size(), disc_.begin());
  pin_wear_ = y[pin_.size() + disc_.size()];
  disc_wear_ = y[pin_.size() + disc_.size() + 1];
  s_ = s;
}

void PinOnDisc::derivative(double s, const double* y, double* dyds, PinOnDiscSample& sample) {
  set_state(y, s);
  evaluate(s, sample, &pin_rate_, &disc_rate_);
  const std::size_t np = pin_.size(), nd = disc_.size();
  std::copy(pin_rate_.begin(), pin_rate_.end(), dyds);
  for (std::size_t i = 0; i < nd; ++i) dyds[np + i] = -disc_rate_[i];
  dyds[np + nd] = last_pin_volume_rate_;
  dyds[np + nd + 1] = last_disc_volume_rate_;
}

}  // namespace wearscale::tribometer
