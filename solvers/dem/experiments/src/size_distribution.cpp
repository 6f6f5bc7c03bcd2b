#include "wearscale/dem/size_distribution.hpp"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_randist.h>

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/roots.hpp"

namespace wearscale::dem {

LogNormal lognormal_of_mode_and_sd(double mode, double sd) {
  if (!(mode > 0.0) || !(sd >= 0.0) || !std::isfinite(mode) || !std::isfinite(sd))
    throw InputError(fmt::format("log-normal size distribution: mode = {}, sd = {}; allowed: mode > 0, sd ≥ 0",
                                 mode, sd));
  if (sd == 0.0) return {std::log(mode), 0.0};
  // s = σ²: (e^s − 1) e^{3s} = (sd/mode)²; increasing from 0 at s = 0, and at
  // s = ln(1 + r²) it is ≥ r² (since e^{3s} ≥ 1): the root lies in between.
  const double r2 = (sd / mode) * (sd / mode);
  const auto f = [r2](double s) { return std::expm1(s) * std::exp(3.0 * s) - r2; };
  const double hi = std::log1p(r2);
  const double s = find_root(f, 0.0, hi, 1e-15 * hi, "log-normal of mode and sd");
  return {std::log(mode) + s, std::sqrt(s)};  // mode = e^{μ−σ²}
}

namespace {
void check(const SizeDistribution& d) {
  if (!(d.smallest > 0.0 && d.smallest <= d.mode && d.mode <= d.largest && std::isfinite(d.largest)))
    throw InputError(fmt::format(
        "particle size distribution: d_s = {}, d0 = {}, d_l = {}; allowed: 0 < d_s ≤ d0 ≤ d_l", d.smallest,
        d.mode, d.largest));
  if (!(d.relative_sd >= 0.0) || !std::isfinite(d.relative_sd))
    throw InputError(fmt::format("particle size distribution: relative sd = {}; allowed: ≥ 0", d.relative_sd));
}
}  // namespace

LogNormal lognormal_of(const SizeDistribution& d) {
  check(d);
  return lognormal_of_mode_and_sd(d.mode, d.relative_sd * (d.largest - d.smallest));  // §6.2.2
}

double truncated_density(const SizeDistribution& d, double x) {
  const LogNormal l = lognormal_of(d);
  if (x < d.smallest || x > d.largest || l.sigma == 0.0) return 0.0;
  const double mass = gsl_cdf_lognormal_P(d.largest, l.mu, l.sigma) - gsl_cdf_lognormal_P(d.smallest, l.mu, l.sigma);
  return gsl_ran_lognormal_pdf(x, l.mu, l.sigma) / mass;
}

DiameterSampler::DiameterSampler(const SizeDistribution& d)
    : law_(lognormal_of(d)), lo_(d.smallest), hi_(d.largest) {
  if (law_.sigma > 0.0) {
    p_lo_ = gsl_cdf_lognormal_P(lo_, law_.mu, law_.sigma);
    p_hi_ = gsl_cdf_lognormal_P(hi_, law_.mu, law_.sigma);
  }
}

double DiameterSampler::operator()(Random& random) const {
  const double u = random.uniform();
  // Without spread, or with [d_s, d_l] so far in a tail that its probability
  // underflows, every particle has the mode (or the nearest bound).
  if (law_.sigma == 0.0 || !(p_hi_ > p_lo_)) return std::clamp(std::exp(law_.mu - law_.sigma * law_.sigma), lo_, hi_);
  const double p = p_lo_ + u * (p_hi_ - p_lo_);
  return std::clamp(gsl_cdf_lognormal_Pinv(p, law_.mu, law_.sigma), lo_, hi_);
}

std::vector<double> sample_diameters(const SizeDistribution& d, std::size_t n, std::uint64_t seed) {
  const DiameterSampler draw(d);
  Random random(seed);
  std::vector<double> out(n);
  for (auto& x : out) x = draw(random);
  return out;
}

}  // namespace wearscale::dem
