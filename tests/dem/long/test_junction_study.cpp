// Fig. 7.2 at the thesis' own cell (§7.1.1): SiO2 (σ_m,T = 9 GPa, Table 6.5),
// d0 = 1.5 nm on an HCP lattice 37.5 × 36.4 × 2.45 nm³ (one HCP cell deep, the
// thesis' 2.4 nm), v = 10 m/s, Δt = 0.1 Δt_c, no global damping; D = 5, 10,
// 20, 37.5 nm under p_N = 0…6 GPa, slid over one L. 28 runs on two threads:
// about 25 min of CPU. tests/dem/test_junction_strength.cpp checks the same
// facts on a reduced grid.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <thread>
#include <vector>

#include "../thesis_junction_cell.hpp"
#include "wearscale/dem/junction_strength.hpp"
#include "wearscale/materials/material.hpp"

using namespace wearscale;
using namespace wearscale::dem;

namespace {

const std::vector<double> diameters{5e-9, 10e-9, 20e-9, 37.5e-9};
const std::vector<double> pressures{0.0, 1e9, 2e9, 3e9, 4e9, 5e9, 6e9};

struct Grid {
  // results[d][p]
  std::vector<std::vector<JunctionStrengthResult>> results;
};

Grid thesis_grid() {
  std::vector<JunctionStrengthSpec> specs;
  for (double d : diameters)
    for (double p : pressures) {
      specs.push_back(test_support::thesis_junction_cell(d, p, 10.0));
    }
  std::vector<JunctionStrengthResult> flat(specs.size());
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t k = next++; k < specs.size(); k = next++) flat[k] = run_junction_strength(specs[k]);
  };
  std::thread other(work);
  work();
  other.join();
  Grid g;
  g.results.resize(diameters.size());
  for (std::size_t d = 0; d < diameters.size(); ++d)
    for (std::size_t p = 0; p < pressures.size(); ++p) {
      const auto& r = flat[d * pressures.size() + p];
      std::printf("measured: D = %4.1f nm, p_N = %.0f GPa: peak p_T %5.2f GPa, steady %5.2f GPa, A/A0 %.2f → %.2f → %.2f, "
                  "%s (rolling %.2f, misfit %.2f)\n",
                  diameters[d] * 1e9, pressures[p] / 1e9, r.peak_tangential / 1e9, r.steady_tangential / 1e9,
                  r.initial_contact_ratio, r.loaded_contact_ratio, r.final_contact_ratio, r.verdict().c_str(),
                  r.rolling_rate, r.rigid_residual);
      g.results[d].push_back(r);
    }
  std::vector<JunctionPoint> points;
  for (const auto& r : flat)
    points.push_back({0.0, r.initial_contact_ratio, r.loaded_contact_ratio, r.final_contact_ratio, r.peak_tangential,
                      r.steady_tangential, r.outcome == JunctionStrengthResult::Outcome::Flattened});
  for (std::size_t k = 0; k < flat.size(); ++k) points[k].pressure = specs[k].pressure;
  const auto fit = fit_junction_law(points);
  std::printf("measured: fit (7.9)-(7.10): σ = %.3g GPa, p_crit = %.3g GPa (%s), sliding %.3g GPa, μ0 = %.3g\n",
              fit.shear_strength / 1e9, fit.p_crit / 1e9, fit.p_crit_source.c_str(), fit.steady_strength / 1e9, fit.mu0);
  return g;
}

const Grid& grid() {
  static const Grid g = thesis_grid();
  return g;
}

}  // namespace

// "All the points seem to lie above the p_T = p_N line" (Fig. 7.2), within 5 %.
TEST(JunctionStudy, ThesisCellEveryPointLiesAboveTheLinePTEqualsPN) {
  const auto& r = grid().results;
  for (std::size_t d = 0; d < diameters.size(); ++d)
    for (std::size_t p = 0; p < pressures.size(); ++p)
      EXPECT_GE(r[d][p].peak_tangential, 0.95 * pressures[p]) << "D = " << diameters[d] << ", p_N = " << pressures[p];
}

// "The general tendency is to have a larger shear resistance p_T when the
// junction is wider", except for junctions the load flattened into a wider
// one (§7.1.1: D = 5 and 10 nm "sometimes exhibiting higher resistances",
// "the same crushing phenomenon happens to larger junctions when p_N is
// greater"): among the junctions that kept their size, and over all four
// sizes at p_N = 0, where nothing crushes them.
TEST(JunctionStudy, ThesisCellResistanceRisesWithTheJunctionsSize) {
  const auto& r = grid().results;
  for (std::size_t d = 1; d < diameters.size(); ++d)
    EXPECT_GT(r[d][0].peak_tangential, r[d - 1][0].peak_tangential) << "p_N = 0, D = " << diameters[d];
  for (std::size_t p = 0; p < pressures.size(); ++p) {
    double previous = 0.0;
    for (std::size_t d = 0; d < diameters.size(); ++d) {
      if (r[d][p].outcome == JunctionStrengthResult::Outcome::Flattened) continue;
      EXPECT_GT(r[d][p].peak_tangential, previous) << "p_N = " << pressures[p] << ", D = " << diameters[d];
      previous = r[d][p].peak_tangential;
    }
  }
}

// "Junctions smaller than L usually detach into a rolling particle"; those
// below d* ≈ 18 nm (6.65) are "flattened into a wider junction" by the load.
// Measured: D = 20 nm detaches for p_N ≤ 2 GPa (rolling rate ≈ 1) and is
// crushed above; D = 5 and 10 nm are flattened from 1 GPa on (at 0 GPa D = 5
// nm, three particles across, rolls away and D = 10 nm shears).
TEST(JunctionStudy, ThesisCellLargeJunctionsDetachAndSmallOnesAreCrushed) {
  const auto& r = grid().results;
  for (std::size_t p = 0; p < pressures.size() && pressures[p] <= 2e9; ++p)
    EXPECT_EQ(r[2][p].verdict(), "detached") << "D = 20 nm, p_N = " << pressures[p];
  for (std::size_t d = 0; d < 2; ++d)
    for (std::size_t p = 1; p < pressures.size(); ++p)
      EXPECT_EQ(r[d][p].verdict(), "flattened") << "D = " << diameters[d] << ", p_N = " << pressures[p];
}

// "At D = L, the resistance is equal to the shear strength of the material",
// which the thesis reads off as 7.5 GPa (7.11). Not reproduced: this DEM's
// full contact peaks at 9.1-10.2 GPa (falling with p_N), 22-35 % above, with
// the same particles (σ_m,T = 9 GPa) and the thesis' force law. The thesis'
// LAMMPS pair style loses the tangential history of cohesive pairs at
// neighbour rebuilds; LAMMPS with it kept gives 10.9 GPa on this cell at
// p_N = 0 (bench/dem/thesis_lammps/README.md). Characterised here (docs/dem.md).
TEST(JunctionStudy, ThesisCellFullContactPeaksAboveTheThesisStrength) {
  const auto& full = grid().results[3];
  double sum = 0.0;
  for (const auto& r : full) sum += r.peak_tangential;
  const double mean = sum / static_cast<double>(full.size());
  std::printf("measured: D = L mean peak p_T %.3g GPa (thesis 7.5 GPa)\n", mean / 1e9);
  EXPECT_NEAR(mean, 9.53e9, 0.05 * 9.53e9);
  EXPECT_GT(mean, 1.15 * 7.5e9);  // the discrepancy, stated
  for (const auto& r : full) EXPECT_DOUBLE_EQ(r.final_contact_ratio, 1.0);
}

// The same full contact with the history transfer of the thesis' LAMMPS runs
// (tangential histories carried over neighbour rebuilds for touching pairs
// only): the thesis' 7.5 GPa (7.11) within 15 %, at p_N = 0 and 3 GPa, in
// two threads. Measured: 7.51 and 7.88 GPa (LAMMPS with the thesis' style on
// this cell: 6.2-7.9 GPa, bench/dem/thesis_lammps/README.md).
TEST(JunctionStudy, WithTheThesisCodesHistoryTransferTheFullContactIsTheThesisStrength) {
  std::vector<JunctionStrengthResult> out(2);
  auto run = [&](std::size_t k, double pressure) {
    auto s = test_support::thesis_junction_cell(test_support::thesis_cell_length, pressure, 10.0);
    s.history_of_touching_pairs_only = true;
    out[k] = run_junction_strength(s);
  };
  std::thread other(run, 1, 3e9);
  run(0, 0.0);
  other.join();
  for (const auto& r : out) {
    std::printf("measured: D = L, thesis-code history: peak p_T %.3g GPa (thesis 7.5 GPa)\n", r.peak_tangential / 1e9);
    EXPECT_NEAR(r.peak_tangential, 7.5e9, 0.15 * 7.5e9);
    EXPECT_DOUBLE_EQ(r.final_contact_ratio, 1.0);
  }
}
