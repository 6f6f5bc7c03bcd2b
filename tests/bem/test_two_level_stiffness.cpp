// The two-level approximation M of the half-space's stiffness S (Ŝ = E*|q|/2):
// symmetric, positive, within a fixed factor of S at every wavelength whatever
// the resolution, and the preconditioner of a rough contact that keeps S's
// iterations (the rough case's iteration counts are in test_rough_contact.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "wearscale/bem/half_space.hpp"
#include "wearscale/bem/normal_operator.hpp"
#include "wearscale/bem/two_level_stiffness.hpp"

using namespace wearscale;
using namespace wearscale::bem;

namespace {
RealField random_field(const Grid2D& g, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  RealField f(g);
  for (double& v : f) v = normal(rng);
  return f;
}

double dot(const RealField& a, const RealField& b) {
  double s = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) s += a[k] * b[k];
  return s;
}

// min and max over the grid's Fourier modes (cosines and sines, the mean
// excepted) of ⟨e, M e⟩ / ⟨e, S e⟩.
std::pair<double, double> rayleigh_range(const Grid2D& g, double e_star) {
  TwoLevelStiffness m(g, e_star);
  HalfSpaceNormal s(g, e_star, Boundary::Periodic);
  RealField e(g), me(g), se(g);
  double lo = 1e300, hi = 0.0;
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j <= g.ny / 2; ++j)
      for (const bool sine : {false, true}) {
        if (i == 0 && j == 0) continue;
        const double kx = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(g.nx);
        const double ky = 2.0 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(g.ny);
        for (std::size_t a = 0; a < g.nx; ++a)
          for (std::size_t b = 0; b < g.ny; ++b) {
            const double phase = kx * static_cast<double>(a) + ky * static_cast<double>(b);
            e(a, b) = sine ? std::sin(phase) : std::cos(phase);
          }
        const double se_e = (s.stiffness(e, se), dot(e, se));
        if (se_e < 1e-9 * dot(e, e)) continue;  // a sine of a Nyquist mode: zero everywhere
        m.apply(e, me);
        const double ratio = dot(e, me) / se_e;
        lo = std::min(lo, ratio);
        hi = std::max(hi, ratio);
      }
  return {lo, hi};
}
}  // namespace

TEST(TwoLevelStiffness, IsSymmetric) {
  // P = 4 Rᵀ and a symmetric coarse operator and stencil: ⟨x, M y⟩ = ⟨M x, y⟩,
  // on a grid of unequal spacings.
  const Grid2D g(64, 48, 2.0, 1.0);
  TwoLevelStiffness m(g, 3.0);
  const RealField x = random_field(g, 1), y = random_field(g, 2);
  RealField mx(g), my(g);
  m.apply(x, mx);
  m.apply(y, my);
  EXPECT_NEAR(dot(x, my), dot(mx, y), 1e-12 * std::sqrt(dot(mx, mx) * dot(y, y)));
}

TEST(TwoLevelStiffness, StaysWithinAFixedFactorOfTheStiffnessAtEveryWavelengthWhateverTheResolution) {
  // Every Fourier mode's ⟨e, M e⟩/⟨e, S e⟩ lies in one band, the same at 16², 32²
  // and 64²: the preconditioned operator's spread does not grow with n.
  // Measured: 0.7146–1.0566 (16²), 0.7146–1.0625 (32², 64²): a factor 1.49.
  for (const std::size_t n : {16u, 32u, 64u}) {
    const auto [lo, hi] = rayleigh_range(Grid2D::square(n, 1e-3), 2e11);
    EXPECT_GT(lo, 0.70) << n << "²";
    EXPECT_LT(hi, 1.08) << n << "²";
    EXPECT_LT(hi / lo, 1.5) << n << "²";
    RecordProperty("range_" + std::to_string(n), std::to_string(lo) + " – " + std::to_string(hi));
  }
}

TEST(TwoLevelStiffness, IsPositiveOnRandomFields) {
  const Grid2D g(128, 96, 1.0, 0.75);
  TwoLevelStiffness m(g, 1.0);
  RealField mx(g);
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const RealField x = random_field(g, seed);
    m.apply(x, mx);
    EXPECT_GT(dot(x, mx), 0.0) << "seed " << seed;
  }
}

TEST(TwoLevelStiffness, AGridWithoutACoarserOneGetsTheStiffnessItself) {
  // An odd grid (no 2× coarser grid) and a free window: the body applies S.
  for (const auto& [g, boundary] : {std::pair{Grid2D(33, 32, 1.0, 1.0), Boundary::Periodic},
                                    std::pair{Grid2D(32, 32, 1.0, 1.0), Boundary::Free}}) {
    EXPECT_EQ(TwoLevelStiffness::supports(g), g.nx % 2 == 0);
    HalfSpaceNormal body(g, 1.0, boundary);
    const RealField r = random_field(g, 3);
    RealField z1(g), z2(g);
    body.stiffness(r, z1);
    body.two_level_stiffness(r, z2);
    for (std::size_t k = 0; k < r.size(); ++k) ASSERT_EQ(z1[k], z2[k]);
  }
}
