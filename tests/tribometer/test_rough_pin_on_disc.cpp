// Rough pin and disc surfaces in the pin-on-disc model: the roughness measure
// sees roughness and not form; the oxide of a rough disc follows its surface;
// the resolved strip holds exactly the disc's worn volume from its rough start;
// a rough disc on the averaged track is refused.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <random>

#include "adaptive_restart.hpp"
#include "thesis_pin_on_disc.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/io/checkpoint.hpp"

namespace wearscale::tribometer {
namespace {

using test_support::thesis_setup;

// A field of nx × ny cells of size dx: f(x, y) at x = i·dx, y = j·dx.
template <class F>
std::vector<double> field(std::size_t nx, std::size_t ny, double dx, F f) {
  std::vector<double> h(nx * ny);
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < ny; ++j) h[i * ny + j] = f(static_cast<double>(i) * dx, static_cast<double>(j) * dx);
  return h;
}

TEST(RoughPinOnDisc, TheRoughnessMeasureRemovesTheFormAndKeepsTheRoughness) {
  // A sine of amplitude A (Sq = A/√2, h'_RMS by differences A q sin(q dx/2)/(q dx/2)/√2) on a sphere's cap
  // to second order (R = 3 mm) tilted by 1e-3, over a disc-shaped region of 40 cells radius.
  const std::size_t n = 128;
  const double dx = 1e-5, a = 1e-7, q = 2.0 * std::numbers::pi / (16.0 * dx), r = 3e-3, c = 0.5 * n * dx;
  const auto form = [&](double x, double y) { return -((x - c) * (x - c) + (y - c) * (y - c)) / (2.0 * r) + 1e-3 * x; };
  const auto h = field(n, n, dx, [&](double x, double y) { return form(x, y) + a * std::sin(q * x); });
  std::vector<char> in(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) in[i * n + j] = std::hypot(i - 64.0, j - 64.0) < 40.0;
  const auto rough = region_roughness(h.data(), in.data(), n, n, dx, dx);
  EXPECT_NEAR(rough.sq, a / std::sqrt(2.0), 0.02 * a / std::sqrt(2.0));
  const double slope = a * q * std::sin(0.5 * q * dx) / (0.5 * q * dx) / std::sqrt(2.0);
  EXPECT_NEAR(rough.hprime_rms, slope, 0.02 * slope);
  // The form alone: no roughness.
  const auto smooth = field(n, n, dx, form);
  const auto none = region_roughness(smooth.data(), in.data(), n, n, dx, dx);
  EXPECT_LT(none.sq, 0.01 * a);
  // Fewer than 3 cells: no roughness to speak of.
  std::vector<char> two(n * n, 0);
  two[0] = two[1] = 1;
  EXPECT_TRUE(std::isnan(region_roughness(h.data(), two.data(), n, n, dx, dx).sq));
}

TEST(RoughPinOnDisc, TheOxideFollowsTheRoughDiscSoItsValleysAreStillOxide) {
  // Heights of ±2 µm on a 1 µm oxide: the valleys are below the layer's depth measured from a flat, yet oxide.
  auto setup = thesis_setup(1e-6);
  setup.grid = 16;
  setup.distance = 0.01;
  setup.track = Track::Resolved;
  std::mt19937_64 rng(3);
  setup.disc_roughness.resize(setup.grid * setup.track_cells());
  for (double& v : setup.disc_roughness) v = (rng() % 2 == 0 ? 2e-6 : -2e-6);
  setup.measure_roughness = true;
  PinOnDisc model(setup);
  const auto layer = model.layer_cells(0.0, model.state().data());
  EXPECT_EQ(std::count(layer.begin(), layer.end(), 1), static_cast<long>(layer.size()));
}

TEST(RoughPinOnDisc, TheResolvedStripHoldsTheDiscsWornVolumeFromItsRoughStart) {
  auto setup = thesis_setup(0.0);  // bare Si: every cell wears the disc alone
  setup.grid = 32;
  setup.distance = 0.02;
  setup.track = Track::Resolved;
  const double dx = setup.size / 32.0;
  const double lt = static_cast<double>(setup.track_cells()) * dx;
  setup.disc_roughness = field(32, setup.track_cells(), dx, [&](double x, double y) {
    return 2e-7 * std::sin(2.0 * std::numbers::pi * 4.0 * x / setup.size) *
           std::cos(2.0 * std::numbers::pi * 25.0 * y / lt);
  });
  setup.pin_roughness = field(32, 32, dx, [&](double x, double y) {
    return 2e-7 * std::cos(2.0 * std::numbers::pi * 5.0 * x / setup.size) *
           std::sin(2.0 * std::numbers::pi * 3.0 * y / setup.size);
  });
  setup.measure_roughness = true;
  PinOnDisc model(setup);
  std::vector<PinOnDiscSample> samples;
  model.run([&](const PinOnDiscSample& x) { samples.push_back(x); });
  double volume = 0.0;
  for (std::size_t k = 0; k < model.disc_profile().size(); ++k)
    volume += setup.disc_roughness[k] - model.disc_profile()[k];
  volume *= model.grid().cell_area();
  EXPECT_NEAR(volume, samples.back().disc_wear, 1e-9 * samples.back().disc_wear);
  // Every sample carries the roughness of both worn surfaces.
  EXPECT_TRUE(std::isfinite(samples.back().pin_roughness.sq));
  EXPECT_TRUE(std::isfinite(samples.back().disc_roughness.sq));
  EXPECT_GT(samples.back().disc_roughness.cells, 0.0);
}

TEST(RoughPinOnDisc, AnAdaptiveRoughRunFromAStateSavedAtARestartEndsBitForBitWithItsRoughness) {
  // A rough pin on 0.5 µm of oxide (averaged track), stopped after its 10th step at a restart and resumed
  // in a fresh model: every sample, its roughness included, as in the uninterrupted run.
  auto setup = thesis_setup(0.5e-6);
  setup.grid = 32;
  setup.distance = 0.03;
  const double dx = setup.size / 32.0;
  setup.pin_roughness = field(32, 32, dx, [&](double x, double y) {
    return 3e-7 * std::cos(2.0 * std::numbers::pi * 5.0 * x / setup.size) *
           std::sin(2.0 * std::numbers::pi * 3.0 * y / setup.size);
  });
  setup.measure_roughness = true;
  AdaptiveOptions options;
  options.restart_every = 5;
  const auto run = test_support::adaptive_restart(setup, options, 10);
  const auto& samples = run.resumed;
  const auto& reference = run.uninterrupted;
  ASSERT_EQ(samples.size(), reference.size());
  const auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  for (std::size_t k = 0; k < samples.size(); ++k) {
    ASSERT_TRUE(same(samples[k].friction, reference[k].friction)) << k;
    ASSERT_TRUE(same(samples[k].pin_wear, reference[k].pin_wear)) << k;
    ASSERT_TRUE(same(samples[k].pin_roughness.sq, reference[k].pin_roughness.sq)) << k;
    ASSERT_TRUE(same(samples[k].pin_roughness.hprime_rms, reference[k].pin_roughness.hprime_rms)) << k;
  }
  EXPECT_TRUE(std::isfinite(reference.back().pin_roughness.sq));
}

TEST(RoughPinOnDisc, ARoughDiscOnTheAveragedTrackIsRefused) {
  auto setup = thesis_setup(1e-6);
  setup.grid = 16;
  setup.disc_roughness.assign(16, 0.0);
  EXPECT_THROW(
      {
        try {
          setup.validate();
        } catch (const InputError& e) {
          EXPECT_THAT(e.what(), ::testing::HasSubstr("track = \"resolved\""));
          throw;
        }
      },
      InputError);
}

}  // namespace
}  // namespace wearscale::tribometer
