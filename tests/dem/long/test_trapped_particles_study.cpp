// Loose particles trapped between flat surfaces, §7.3 at the thesis' size
// (Figs. 7.8, 7.9): d0 = 3 nm, L = 300 nm, n = 3 particles (D = 30 nm: the
// thesis does not state D), quasi-2D. Label long; 50 m/s instead of 10 m/s to
// shorten the runs (§7.2.2: no effect of v), the three loads of the first
// test on two threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <thread>

#include "wearscale/dem/trapped_particles.hpp"
#include "wearscale/materials/material.hpp"

using namespace wearscale;
using namespace wearscale::dem;

namespace {
TrappedParticlesSpec thesis_cell(int n) {
  TrappedParticlesSpec s;
  s.cell.material = cohesive_material(materials::silica(), 0.5);
  const double d0 = 3e-9;
  s.cell.d0 = d0;
  s.count = n;
  s.diameter = 30e-9;
  s.cell.box = {300e-9, 3.5 * d0, 30e-9 + 16 * d0};
  s.cell.velocity = 50.0;
  s.cell.sliding_distance = 600e-9;
  s.cell.settle_distance = d0;
  s.cell.record_every = 1000;
  s.fit_from = 0.8;  // the regime reached at the end
  return s;
}

// What a run measured, for the record whether or not it passes.
void print(const char* what, const TrappedParticlesResult& r) {
  std::printf("measured: %s: %zu particles, %ld steps, %s (misfit %.3f), mean p_T %.3g GPa, p_N %.3g GPa, mu %.3f, "
              "band %.3g nm\n",
              what, r.particles, r.steps, r.regime().c_str(), r.mean_residual, r.mean_tangential_force / r.area / 1e9,
              r.mean_pressure / 1e9, r.friction, r.band_thickness * 1e9);
}

double mean_tangential(const TrappedParticlesResult& r, double from, double to) {
  const double end = r.history.back().sliding;
  double sum = 0.0;
  int n = 0;
  for (const auto& h : r.history)
    if (h.time > 0.0 && h.sliding >= from * end && h.sliding <= to * end) {
      sum += h.tangential_force;
      ++n;
    }
  return n > 0 ? sum / n : 0.0;
}
}  // namespace

// Fig. 7.9: for n = 3, p_N ≤ 0.3 GPa rolls (low F_T), 1 GPa goes to a shear
// band (high F_T), and 0.6 GPa rolls first and then transitions to the band.
TEST(TrappedParticlesStudy, ThreeParticlesTransitionNearSixTenthsOfAGigapascal) {
  const auto base = thesis_cell(3);
  const auto sample = make_cell_sample(base.cell);
  // The three loads on one relaxed box, two at a time (two cores).
  auto at = [&](double pressure) {
    auto spec = base;
    spec.cell.pressure = pressure;
    return run_trapped_particles(spec, sample);
  };
  TrappedParticlesResult low, mid, high;
  std::thread other([&] { mid = at(0.6e9); });
  low = at(0.3e9);
  high = at(1.0e9);
  other.join();
  print("n = 3, 0.3 GPa", low);
  print("n = 3, 0.6 GPa", mid);
  print("n = 3, 1 GPa", high);
  std::printf("measured: n = 3, 0.6 GPa: mean F_T over 5-25 %% of the slide %.3g nN, over 75-100 %% %.3g nN\n",
              mean_tangential(mid, 0.05, 0.25) * 1e9, mean_tangential(mid, 0.75, 1.0) * 1e9);
  EXPECT_TRUE(low.rolling) << "misfit " << low.mean_residual;
  EXPECT_FALSE(high.rolling) << "misfit " << high.mean_residual;
  EXPECT_FALSE(mid.rolling) << "misfit " << mid.mean_residual;
  // The transition at 0.6 GPa: low resistance first, high at the end.
  EXPECT_GT(mean_tangential(mid, 0.75, 1.0), 2.0 * mean_tangential(mid, 0.05, 0.25));
  EXPECT_LT(low.mean_tangential_force / low.area, 0.5 * high.mean_tangential_force / high.area);
}

// Fig. 7.9: with fewer particles (n = 2) the same intermediate load goes
// directly to the shear band.
TEST(TrappedParticlesStudy, TwoParticlesAtSixTenthsGoToTheShearBand) {
  auto spec = thesis_cell(2);
  spec.cell.pressure = 0.6e9;
  const auto r = run_trapped_particles(spec);
  print("n = 2, 0.6 GPa", r);
  EXPECT_FALSE(r.rolling) << "misfit " << r.mean_residual;
}
