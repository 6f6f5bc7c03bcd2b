// The sheared rough SiO2 surfaces of §7.2, reduced: a 20 d0 long quasi-2D
// cell (d0 = 3 nm < d* ≈ 18 nm), Sa = 0.04 L, p_N = 0.5 GPa, slid 8 d0 at
// 100 m/s (the thesis slides at 0.1-10 m/s over hundreds of nm: see
// tests/dem/long/test_rough_shear_study.cpp). Asserts what this size can
// show: the carved surfaces have the requested Sa, the wall holds p_N,
// particles are worn (more than half of their initial neighbours lost) and
// Sa evolves. Also the profile generator and the Sa measurement on
// hand-made surfaces.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "wearscale/core/errors.hpp"
#include "wearscale/dem/rough_profile.hpp"
#include "wearscale/dem/rough_shear.hpp"
#include "wearscale/dem/surface_roughness.hpp"
#include "wearscale/materials/material.hpp"

using namespace wearscale;
using namespace wearscale::dem;

TEST(RoughProfile, HasTheRequestedSaZeroMeanAndPeriod) {
  RoughProfileSpec s;
  s.length = 100e-9;
  s.sa = 2e-9;
  s.hurst = 0.8;
  s.k_max = 12;
  s.seed = 7;
  const RoughProfile h(s);
  // On a grid other than the one the scaling used (prime count of points).
  std::vector<double> samples;
  double mean = 0.0;
  for (int i = 0; i < 997; ++i) {
    const double x = s.length * i / 997.0;
    samples.push_back(h(x));
    mean += h(x) / 997.0;
    EXPECT_NEAR(h(x + s.length), h(x), 1e-12 * s.sa);
  }
  EXPECT_NEAR(arithmetic_roughness(samples), s.sa, 0.01 * s.sa);
  EXPECT_NEAR(mean, 0.0, 1e-9 * s.sa);
  // Another seed gives another profile of the same Sa.
  s.seed = 8;
  const RoughProfile g(s);
  EXPECT_GT(std::abs(g(0.3 * s.length) - h(0.3 * s.length)), 1e-3 * s.sa);
  s.hurst = 1.5;
  EXPECT_THROW(RoughProfile{s}, InputError);
}

TEST(SurfaceRoughness, SaOfASinusoidalParticleSurfaceIsTwoAmplitudesOverPi) {
  // Unit spheres whose tops follow z + r = A sin(2πx/L): Sa = 2A/π.
  const double length = 64.0, amplitude = 1.5;
  Particles p;
  Box box;
  box.lo = {0, 0, -10};
  box.hi = {length, 4, 10};
  box.periodic = {true, true, false};
  for (int i = 0; i < 64 * 4; ++i) {
    const double x = 0.25 + 0.25 * i;
    const double top = amplitude * std::sin(2.0 * std::numbers::pi * x / length);
    p.add({{x, 1.0, top - 0.5}, 0.5, 1.0, {}, 0, 0});
    p.add({{x, 2.0, top - 3.0}, 0.5, 1.0, {}, 0, 0});  // buried below: not the surface
  }
  const double sa = surface_roughness(p, box, [](std::size_t) { return true; }, Facing::up, 0.25);
  EXPECT_NEAR(sa, 2.0 * amplitude / std::numbers::pi, 0.01 * amplitude);
  // Seen from above (facing down), the lowest edges: the buried row, same Sa.
  const double below = surface_roughness(p, box, [](std::size_t) { return true; }, Facing::down, 0.25);
  EXPECT_NEAR(below, 2.0 * amplitude / std::numbers::pi, 0.01 * amplitude);
  // A flat surface has Sa = 0.
  for (auto& x : p.position) x.z = 0.0;
  EXPECT_NEAR(surface_roughness(p, box, [](std::size_t) { return true; }, Facing::up, 0.25), 0.0, 1e-12);
}

TEST(RoughShear, ReducedCellWearsUnderTheImposedPressureAndSaEvolves) {
  RoughShearSpec s;
  s.cell.material = cohesive_material(materials::silica(), 0.5);  // Table 6.5, s = ½
  const double d0 = 3e-9;
  s.cell.d0 = d0;
  s.cell.box = {20 * d0, 3.5 * d0, 14 * d0};
  s.cell.pressure = 0.5e9;
  s.cell.velocity = 100.0;
  s.cell.sliding_distance = 8 * d0;
  s.cell.settle_distance = d0;
  s.roughness = 0.04;
  const auto r = run_rough_shear(s);
  EXPECT_NEAR(r.d_star, 18.5e-9, 0.5e-9);  // d0 < d* (6.65)
  // The carved surfaces have the imposed Sa (measured on their particles).
  const auto& first = r.history.front();
  EXPECT_NEAR(r.imposed_roughness, 0.04 * 20 * d0, 0.04 * 20 * d0 * 0.05);  // the relaxed box differs by a few %
  EXPECT_NEAR(first.roughness_bottom, r.imposed_roughness, 0.15 * r.imposed_roughness);
  EXPECT_NEAR(first.roughness_top, r.imposed_roughness, 0.15 * r.imposed_roughness);
  // The pressed wall holds p_N over the second half of the slide.
  EXPECT_NEAR(r.mean_pressure, 0.5e9, 0.1 * 0.5e9);
  // The tangential force history is recorded: one sample per record
  // interval, resisting the slide.
  const long intervals = (r.steps + s.cell.record_every - 1) / s.cell.record_every;
  EXPECT_GE(static_cast<long>(r.history.size()), intervals);
  EXPECT_GT(r.mean_tangential_force, 0.0);
  EXPECT_GE(r.peak_tangential_force, r.mean_tangential_force);
  EXPECT_NEAR(r.history.back().sliding, 8 * d0, 0.05 * d0);
  // Worn particles appear at the interface and their number grows.
  EXPECT_EQ(first.worn, 0.0);
  EXPECT_GE(r.worn, 10u);
  EXPECT_GT(r.history.back().worn, r.history[r.history.size() / 2].worn);
  // Sa evolves: running-in smooths the rough surfaces (by 15-25 % here).
  const double sa0 = 0.5 * (first.roughness_bottom + first.roughness_top);
  const double sa1 = 0.5 * (r.history.back().roughness_bottom + r.history.back().roughness_top);
  EXPECT_LT(sa1, 0.9 * sa0);
}
