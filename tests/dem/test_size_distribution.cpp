// The particle size distribution of the amorphous sample (§6.2.2): a
// log-normal of mode d0 and standard deviation 0.2 (d_l − d_s), truncated to
// [d_s, d_l].
#include <gsl/gsl_cdf.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "input_error_of.hpp"
#include "wearscale/dem/size_distribution.hpp"

using namespace wearscale::dem;

namespace {
// Moments of the truncated density by the midpoint rule on 20000 cells.
struct Moments {
  double mass, mean, sd;
};
Moments truncated_moments(const SizeDistribution& d) {
  const int n = 20000;
  const double h = (d.largest - d.smallest) / n;
  double m0 = 0.0, m1 = 0.0, m2 = 0.0;
  for (int k = 0; k < n; ++k) {
    const double x = d.smallest + (k + 0.5) * h;
    const double f = truncated_density(d, x) * h;
    m0 += f;
    m1 += f * x;
    m2 += f * x * x;
  }
  return {m0, m1 / m0, std::sqrt(m2 / m0 - (m1 / m0) * (m1 / m0))};
}

// The centre of the most populated of `bins` equal bins over [d_s, d_l].
double histogram_mode(const std::vector<double>& x, const SizeDistribution& d, int bins) {
  std::vector<long> count(static_cast<std::size_t>(bins), 0);
  const double h = (d.largest - d.smallest) / bins;
  for (double v : x) ++count[static_cast<std::size_t>(std::min(bins - 1, static_cast<int>((v - d.smallest) / h)))];
  const auto top = std::max_element(count.begin(), count.end()) - count.begin();
  return d.smallest + (static_cast<double>(top) + 0.5) * h;
}

double mean(const std::vector<double>& x) {
  double s = 0.0;
  for (double v : x) s += v;
  return s / static_cast<double>(x.size());
}
double sd(const std::vector<double>& x) {
  const double m = mean(x);
  double s = 0.0;
  for (double v : x) s += (v - m) * (v - m);
  return std::sqrt(s / static_cast<double>(x.size() - 1));
}

// The thesis' bounds d_s = 0.75 d0, d_l = 1.25 d0 (symmetric), and the
// SiO2 junction's d_s = 0.75 d0 with d_l fixed well above d0 (skewed).
const SizeDistribution symmetric{6.0, 4.5, 7.5, 0.2};
const SizeDistribution skewed{1.5, 1.125, 7.5, 0.2};
}  // namespace

TEST(SizeDistribution, LogNormalParametersGiveTheModeAndSdExactly) {
  for (double mode : {1.0, 6e-9, 150.0})
    for (double rel : {1e-4, 0.1, 0.5, 2.0}) {
      const LogNormal l = lognormal_of_mode_and_sd(mode, rel * mode);
      const double s2 = l.sigma * l.sigma;
      EXPECT_NEAR(std::exp(l.mu - s2), mode, 1e-12 * mode);  // mode = e^{μ−σ²}
      const double sd_of = std::sqrt(std::expm1(s2) * std::exp(2.0 * l.mu + s2));
      EXPECT_NEAR(sd_of, rel * mode, 1e-9 * rel * mode) << "mode " << mode << " sd/mode " << rel;
    }
}

TEST(SizeDistribution, StandardDeviationIsFractionOfTheRange) {
  const LogNormal l = lognormal_of(symmetric);
  const double s2 = l.sigma * l.sigma;
  EXPECT_NEAR(std::sqrt(std::expm1(s2) * std::exp(2.0 * l.mu + s2)), 0.2 * (7.5 - 4.5), 1e-12);
}

TEST(SizeDistribution, SamplesRespectTheBounds) {
  for (const auto& d : {symmetric, skewed}) {
    const auto x = sample_diameters(d, 100000, 7);
    EXPECT_GE(*std::min_element(x.begin(), x.end()), d.smallest);
    EXPECT_LE(*std::max_element(x.begin(), x.end()), d.largest);
  }
}

TEST(SizeDistribution, TruncatedDensityPeaksAtD0) {
  for (const auto& d : {symmetric, skewed}) {
    const int n = 100000;
    const double h = (d.largest - d.smallest) / n;
    double best = d.smallest, top = 0.0;
    for (int k = 0; k <= n; ++k) {
      const double x = d.smallest + k * h;
      if (truncated_density(d, x) > top) {
        top = truncated_density(d, x);
        best = x;
      }
    }
    EXPECT_NEAR(best, d.mode, 2.0 * h);
  }
}

TEST(SizeDistribution, SampleModeIsD0WithinTwoPercent) {
  // 10^6 draws in bins of 2 % of d0: the most populated bin is one of the two
  // beside d0 (the neighbours beyond hold 4 % fewer, noise is 0.4 %).
  const auto x = sample_diameters(symmetric, 1000000, 11);
  EXPECT_NEAR(histogram_mode(x, symmetric, 25), symmetric.mode, 0.02 * symmetric.mode);
}

TEST(SizeDistribution, SamplesFollowTheTruncatedLogNormal) {
  // Kolmogorov-Smirnov distance to F(x) = (P(x) − P(d_s)) / (P(d_l) − P(d_s))
  // below its 1 % critical value 1.63/√n (fixed seed: deterministic).
  for (const auto& d : {symmetric, skewed}) {
    const std::size_t n = 100000;
    auto x = sample_diameters(d, n, 13);
    std::sort(x.begin(), x.end());
    const LogNormal l = lognormal_of(d);
    const double p_lo = gsl_cdf_lognormal_P(d.smallest, l.mu, l.sigma);
    const double p_hi = gsl_cdf_lognormal_P(d.largest, l.mu, l.sigma);
    double distance = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      const double f = (gsl_cdf_lognormal_P(x[k], l.mu, l.sigma) - p_lo) / (p_hi - p_lo);
      distance = std::max({distance, std::fabs(f - static_cast<double>(k) / n),
                           std::fabs(f - static_cast<double>(k + 1) / n)});
    }
    EXPECT_LT(distance, 1.63 / std::sqrt(static_cast<double>(n)));
  }
}

TEST(SizeDistribution, SampleMeanAndSdMatchTheTruncatedDistribution) {
  // Truncation narrows the spread below 0.2 (d_l − d_s); the draws follow
  // the truncated density: mean within 0.1 %, sd within 1 % (10^5 draws).
  for (const auto& d : {symmetric, skewed}) {
    const auto x = sample_diameters(d, 100000, 3);
    const Moments m = truncated_moments(d);
    EXPECT_NEAR(m.mass, 1.0, 1e-6);
    EXPECT_NEAR(mean(x), m.mean, 1e-3 * m.mean);
    EXPECT_NEAR(sd(x), m.sd, 1e-2 * m.sd);
    EXPECT_LT(m.sd, 0.2 * (d.largest - d.smallest));
  }
  // The skewed one keeps the mode at d0 but puts its mean above it.
  EXPECT_GT(truncated_moments(skewed).mean, 1.1 * skewed.mode);
}

TEST(SizeDistribution, SameSeedSameDiametersOtherSeedOthers) {
  EXPECT_EQ(sample_diameters(symmetric, 100, 5), sample_diameters(symmetric, 100, 5));
  EXPECT_NE(sample_diameters(symmetric, 100, 5), sample_diameters(symmetric, 100, 6));
}

TEST(SizeDistribution, MonodisperseWhenTheBoundsMeet) {
  const auto x = sample_diameters({2.0, 2.0, 2.0, 0.2}, 10, 1);
  for (double v : x) EXPECT_EQ(v, 2.0);
}

TEST(SizeDistribution, RefusesAModeOutsideTheBounds) {
  EXPECT_NE(input_error_of([] { lognormal_of({1.0, 1.1, 2.0, 0.2}); }).find("0 < d_s ≤ d0 ≤ d_l"), std::string::npos);
  EXPECT_NE(input_error_of([] { lognormal_of({1.0, 0.0, 2.0, 0.2}); }), "no InputError");
  EXPECT_NE(input_error_of([] { lognormal_of({1.0, 0.5, 2.0, -0.1}); }), "no InputError");
}
