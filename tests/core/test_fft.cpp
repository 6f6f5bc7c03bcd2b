// FFTW through the plan cache: exact round trips, the DFT convention, the
// convolution theorem against a direct sum, and plans shared per shape.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "wearscale/core/fft.hpp"

using namespace wearscale;

namespace {
RealField random_field(const Grid2D& g, unsigned seed) {
  RealField f(g);
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  for (auto& v : f) v = n(rng);
  return f;
}
}  // namespace

TEST(FFT, ForwardThenBackwardReturnsTheField) {
  for (auto [nx, ny] : {std::pair{16ul, 16ul}, {12ul, 10ul}, {7ul, 9ul}, {64ul, 32ul}}) {
    const Grid2D g(nx, ny, 1.0, 1.0);
    const RealField h = random_field(g, 1);
    ComplexField spec = ComplexField::spectrum_of(g);
    RealField back(g);
    auto plan = FFTPlanCache::global().plan(g);
    plan->forward(h, spec);
    plan->backward(spec, back);
    for (std::size_t k = 0; k < h.size(); ++k) ASSERT_NEAR(back[k], h[k], 1e-13) << nx << "x" << ny;
  }
}

TEST(FFT, ForwardPreservesItsInput) {
  const Grid2D g(32, 32, 1.0, 1.0);
  const RealField h = random_field(g, 2);
  RealField copy = h;
  ComplexField spec = ComplexField::spectrum_of(g);
  FFTPlanCache::global().plan(g)->forward(copy, spec);
  for (std::size_t k = 0; k < h.size(); ++k) ASSERT_EQ(copy[k], h[k]);
}

TEST(FFT, ACosineLandsOnItsWavenumberWithWeightNOverTwo) {
  // h = cos(2π·3x/Lx): ĥ(k=±3, 0) = N/2, nothing elsewhere (unnormalised forward).
  const Grid2D g(16, 8, 2.0, 1.0);
  RealField h(g);
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) h(i, j) = std::cos(2.0 * std::numbers::pi * 3.0 * g.x(i) / g.lx);
  ComplexField spec = ComplexField::spectrum_of(g);
  FFTPlanCache::global().plan(g)->forward(h, spec);
  const double half_n = 0.5 * static_cast<double>(g.size());
  for (std::size_t i = 0; i < spec.rows(); ++i)
    for (std::size_t j = 0; j < spec.cols(); ++j) {
      const bool peak = j == 0 && std::abs(g.frequency_x(i)) == 3;
      EXPECT_NEAR(std::abs(spec(i, j)), peak ? half_n : 0.0, 1e-11) << i << "," << j;
    }
}

TEST(FFT, ParsevalHoldsForTheHalfSpectrum) {
  const Grid2D g(16, 16, 1.0, 1.0);
  const RealField h = random_field(g, 3);
  ComplexField spec = ComplexField::spectrum_of(g);
  FFTPlanCache::global().plan(g)->forward(h, spec);
  double physical = 0.0, spectral = 0.0;
  for (double v : h) physical += v * v;
  for (std::size_t i = 0; i < spec.rows(); ++i)
    for (std::size_t j = 0; j < spec.cols(); ++j) {
      const double w = (j == 0 || j == g.ny / 2) ? 1.0 : 2.0;  // modes stored once for ±k_y
      spectral += w * std::norm(spec(i, j));
    }
  EXPECT_NEAR(spectral / static_cast<double>(g.size()), physical, 1e-10 * physical);
}

TEST(FFT, ConvolutionTheoremMatchesADirectPeriodicSum) {
  const Grid2D g(8, 6, 1.0, 1.0);
  const RealField a = random_field(g, 4), b = random_field(g, 5);
  auto plan = FFTPlanCache::global().plan(g);
  ComplexField fa = ComplexField::spectrum_of(g), fb = ComplexField::spectrum_of(g);
  plan->forward(a, fa);
  plan->forward(b, fb);
  for (std::size_t k = 0; k < fa.size(); ++k) fa[k] *= fb[k];
  RealField conv(g);
  plan->backward(fa, conv);
  for (long i = 0; i < 8; ++i)
    for (long j = 0; j < 6; ++j) {
      double direct = 0.0;
      for (long p = 0; p < 8; ++p)
        for (long q = 0; q < 6; ++q) direct += a(static_cast<std::size_t>(p), static_cast<std::size_t>(q)) * b.periodic(i - p, j - q);
      ASSERT_NEAR(conv(static_cast<std::size_t>(i), static_cast<std::size_t>(j)), direct, 1e-12);
    }
}

TEST(FFTPlanCache, TheSameShapeGetsTheSamePlanObject) {
  auto& cache = FFTPlanCache::global();
  auto p1 = cache.plan(48, 40);
  auto p2 = cache.plan(Grid2D(48, 40, 3.0, 7.0));  // physical size does not matter
  auto p3 = cache.plan(40, 48);
  EXPECT_EQ(p1.get(), p2.get());
  EXPECT_NE(p1.get(), p3.get());
}

TEST(FFTPlanCache, SmallGridsUseOneThread) {
  FFTPlanCache::global().set_threads(2, 128 * 128);
  EXPECT_EQ(FFTPlanCache::global().plan(20, 20)->threads(), 1);
  EXPECT_EQ(FFTPlanCache::global().plan(256, 128)->threads(), 2);
  FFTPlanCache::global().set_threads(0);
}

TEST(FFTPlan, RefusesAFieldOfAnotherShape) {
  const Grid2D g(16, 16, 1.0, 1.0), other(16, 8, 1.0, 1.0);
  RealField h(other);
  ComplexField spec = ComplexField::spectrum_of(g);
  EXPECT_THROW(FFTPlanCache::global().plan(g)->forward(h, spec), std::invalid_argument);
}

TEST(FFTPlanCache, WisdomRoundTripsThroughAFile) {
  const auto file = std::filesystem::temp_directory_path() / "wearscale_test.wisdom";
  FFTPlanCache::global().plan(30, 30);
  FFTPlanCache::global().export_wisdom(file);
  EXPECT_TRUE(std::filesystem::exists(file));
  EXPECT_TRUE(FFTPlanCache::global().import_wisdom(file));
  std::filesystem::remove(file);
}
