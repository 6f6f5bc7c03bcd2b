#pragma once
// The particle diameters of an amorphous sample (§6.2.2): a log-normal
// distribution of mode d0 and standard deviation 0.2 (d_l − d_s), truncated
// to [d_s, d_l].
#include <cstddef>
#include <cstdint>
#include <vector>

#include "wearscale/dem/random.hpp"

namespace wearscale::dem {

struct SizeDistribution {
  double mode = 1.0;         ///< d0, the most frequent diameter
  double smallest = 0.75;    ///< d_s
  double largest = 1.25;     ///< d_l
  double relative_sd = 0.2;  ///< standard deviation as a fraction of d_l − d_s
};

/// The parameters of ln d ~ N(μ, σ²) (GSL's ζ = μ and σ).
struct LogNormal {
  double mu = 0.0;
  double sigma = 0.0;
};

/// The log-normal with the given mode and standard deviation (of the
/// untruncated distribution). With u = e^{σ²}: mode = e^{μ−σ²} and
/// sd² = mode² (u − 1) u³, a quartic with one root u > 1, found by bracketed
/// Brent iterations on σ²; then μ = ln(mode) + σ².
LogNormal lognormal_of_mode_and_sd(double mode, double sd);

/// The untruncated log-normal of a size distribution; InputError unless
/// 0 < d_s ≤ d0 ≤ d_l and relative_sd ≥ 0.
LogNormal lognormal_of(const SizeDistribution& d);

/// The probability density of the truncated distribution at diameter x
/// (0 outside [d_s, d_l]; a monodisperse distribution has no density).
double truncated_density(const SizeDistribution& d, double x);

/// Draws diameters from the truncated distribution by inverting its
/// cumulative distribution function: d = F⁻¹(F(d_s) + U (F(d_l) − F(d_s))).
class DiameterSampler {
 public:
  explicit DiameterSampler(const SizeDistribution& d);
  double operator()(Random& random) const;

 private:
  LogNormal law_;
  double lo_ = 0.0, hi_ = 0.0;      // d_s, d_l
  double p_lo_ = 0.0, p_hi_ = 1.0;  // F(d_s), F(d_l)
};

/// `n` diameters drawn with a Random of this seed.
std::vector<double> sample_diameters(const SizeDistribution& d, std::size_t n, std::uint64_t seed);

}  // namespace wearscale::dem
