#include "wearscale/wear/micro_contact_map.hpp"

#include <cmath>
#include <memory>
#include <numbers>

#include <fmt/format.h>

#include "wearscale/bem/normal_contact.hpp"
#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/core/errors.hpp"

namespace wearscale::wear {

std::size_t MicroContactMap::points() const {
  std::size_t n = 0;
  for (auto c : contact) n += c;
  return n;
}

double MicroContactMap::contact_fraction() const {
  return static_cast<double>(points()) / static_cast<double>(grid.size());
}

MicroContactMap contact_from_pressure(const RealField& pressure) {
  MicroContactMap m(pressure.grid());
  for (std::size_t k = 0; k < pressure.size(); ++k) m.contact[k] = pressure[k] > 0.0 ? 1 : 0;
  return m;
}

MicroContactMap two_circles(const Grid2D& grid, double d, double l, double theta) {
  if (std::abs(grid.dx() - grid.dy()) > 1e-12 * grid.dx())
    throw InputError(fmt::format("two circles: grid {} is not allowed; allowed: square cells", grid.to_string()));
  if (!(d > 0.0) || !std::isfinite(d))
    throw InputError(fmt::format("two circles: diameter d = {} is not allowed; allowed: d > 0", d));
  if (!(l >= d) || !std::isfinite(l))
    throw InputError(fmt::format("two circles: distance l = {} is not allowed; allowed: l ≥ d = {}", l, d));
  const double span_x = std::abs(l * std::cos(theta)) + d, span_y = std::abs(l * std::sin(theta)) + d;
  if (span_x > grid.lx || span_y > grid.ly)
    throw InputError(fmt::format("two circles: d = {}, l = {} do not fit in the cell {}", d, l, grid.to_string()));
  MicroContactMap m(grid);
  const double cx = 0.5 * grid.lx, cy = 0.5 * grid.ly;
  const double ox = 0.5 * l * std::cos(theta), oy = 0.5 * l * std::sin(theta);
  const double r2 = 0.25 * d * d * (1.0 + 1e-12);
  for (std::size_t i = 0; i < grid.nx; ++i)
    for (std::size_t j = 0; j < grid.ny; ++j) {
      const double x = grid.x(i), y = grid.y(j);
      const double a = (x - cx + ox) * (x - cx + ox) + (y - cy + oy) * (y - cy + oy);
      const double b = (x - cx - ox) * (x - cx - ox) + (y - cy - oy) * (y - cy - oy);
      m.contact[grid.index(i, j)] = (a <= r2 || b <= r2) ? 1 : 0;
    }
  return m;
}

double normal_pressure(double p_tilde, double h_prime_rms, double e_star) {
  return p_tilde * h_prime_rms * e_star / std::sqrt(2.0 * std::numbers::pi);  // (5.1)
}

void validate(const RoughContactSpec& s) {
  if (s.n < 16 || s.n > 8192 || s.n % 2 != 0)
    throw InputError(fmt::format("rough contact: n = {} is not allowed; allowed: even, 16 ≤ n ≤ 8192", s.n));
  if (!(s.hurst > 0.0 && s.hurst <= 1.0))
    throw InputError(fmt::format("rough contact: Hurst exponent H = {} is not allowed; allowed: 0 < H ≤ 1", s.hurst));
  if (!(s.k_l >= 1.0 && s.k_l <= s.k_s && s.k_s <= static_cast<double>(s.n) / 2.0))
    throw InputError(fmt::format("rough contact: q_l = {}, q_s = {} (in 2π/L) are not allowed; allowed: "
                                 "1 ≤ q_l ≤ q_s ≤ n/2 = {}", s.k_l, s.k_s, s.n / 2));
  if (!(s.poisson > -1.0 && s.poisson <= 0.5))
    throw InputError(fmt::format("rough contact: ν = {} is not allowed; allowed: −1 < ν ≤ 0.5", s.poisson));
  if (!(s.h_prime_rms > 0.0) || !std::isfinite(s.h_prime_rms))
    throw InputError(fmt::format("rough contact: h'_RMS = {} is not allowed; allowed: > 0", s.h_prime_rms));
}

struct RoughContactSeries::Impl {
  RoughContactSpec spec;
  RealField surface;
  std::unique_ptr<bem::NormalContact> contact;
};

RoughContactSeries::RoughContactSeries(const RoughContactSpec& spec, std::uint64_t seed) : impl_(new Impl) {
  validate(spec);
  impl_->spec = spec;
  bem::RoughSurfaceSpec rs;
  rs.grid = Grid2D::square(spec.n, 1.0);
  rs.hurst = spec.hurst;
  rs.k_l = spec.k_l;
  rs.k_r = spec.k_l;  // q_r = q_l (§5.1)
  rs.k_s = spec.k_s;
  rs.seed = seed;
  impl_->surface = bem::generate_surface(rs, bem::RoughnessMeasure::HPrimeRms, spec.h_prime_rms);
  // E* = 1: the contact map depends on p̃_N only.
  impl_->contact = std::make_unique<bem::NormalContact>(impl_->surface, 1.0);
}

RoughContactSeries::~RoughContactSeries() { delete impl_; }

const RealField& RoughContactSeries::surface() const { return impl_->surface; }

MicroContactMap RoughContactSeries::at_load(double p_tilde) {
  if (!(p_tilde > 0.0) || !std::isfinite(p_tilde))
    throw InputError(fmt::format("rough contact: normalized load p̃_N = {} is not allowed; allowed: > 0", p_tilde));
  bem::ContactOptions opt;
  opt.tolerance = impl_->spec.tolerance;
  opt.max_iterations = impl_->spec.max_iterations;
  opt.predict_load = true;  // a series walks the loads on one surface: start from the secant of the last two
  const auto r = impl_->contact->solve_mean_pressure(normal_pressure(p_tilde, impl_->spec.h_prime_rms, 1.0), opt);
  iterations_ = r.iterations;
  return contact_from_pressure(impl_->contact->pressure());
}

}  // namespace wearscale::wear
