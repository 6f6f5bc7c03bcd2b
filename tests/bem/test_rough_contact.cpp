// Rough contact at small load (1.11, §5.1): the real contact area grows in
// proportion to the load, A/A0 = κ p_N/(E* h'_RMS), with κ between the
// √(8/π) of Persson's theory and the √(2π) of Bush et al.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "wearscale/bem/normal_contact.hpp"
#include "wearscale/bem/surface_generator.hpp"

using namespace wearscale;
using namespace wearscale::bem;

TEST(RoughContact, ContactAreaIsProportionalToLoadWithKappaBetweenPerssonAndBush) {
  // H = 0.8, k_l = 8 as the thesis' wear-map surfaces (ch. 5), k_s = 32 on
  // 1024² points: 32 points per shortest wavelength. Counting points with
  // p > 0 overestimates A when micro-contacts span few points: on 512² with
  // k_s = 64 the same count gives κ = 2.56-2.66 at p_N = 0.005 E* h'_RMS,
  // above √(2π); here κ = 2.32-2.47 (seeds 1-2).
  RoughSurfaceSpec spec;
  spec.grid = Grid2D::square(1024, 1.0);
  spec.hurst = 0.8;
  spec.k_l = spec.k_r = 8.0;
  spec.k_s = 32.0;
  const double e_star = 1.0, hprime = 1.0;
  const double kappa_persson = std::sqrt(8.0 / std::numbers::pi), kappa_bush = std::sqrt(2.0 * std::numbers::pi);
  for (std::uint64_t seed : {1u, 2u}) {
    spec.seed = seed;
    NormalContact contact(generate_surface(spec, RoughnessMeasure::HPrimeRms, hprime), e_star);
    std::vector<double> kappa;
    for (double load : {0.01, 0.02, 0.04}) {  // p_N / (E* h'_RMS)
      const auto r = contact.solve_mean_pressure(load * e_star * hprime, {1e-10, 10000});
      kappa.push_back(r.contact_fraction / load);
      EXPECT_GT(kappa.back(), kappa_persson) << "seed " << seed << ", load " << load;
      EXPECT_LT(kappa.back(), kappa_bush) << "seed " << seed << ", load " << load;
      RecordProperty("kappa_seed" + std::to_string(seed) + "_load" + std::to_string(load), std::to_string(kappa.back()));
    }
    // Proportional: κ varies by less than 10 % over a fourfold load range.
    EXPECT_LT(std::abs(kappa.back() / kappa.front() - 1.0), 0.10) << "seed " << seed;
  }
}
