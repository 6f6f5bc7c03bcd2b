// The closed forms of the stored elastic energy, (4.33) for one sheared circular
// micro-contact and (4.44) for two, against a direct evaluation of (4.1)/(4.6)
// with the periodic half-space of the BEM (as Fig. 4.4 does).
//
// The BEM cell is periodic and drops the mean (q = 0) displacement, which
// shifts the energy of a net force F by c F²/L (a lattice sum over the images);
// two cells of side L and 2L at the same spacing remove that term by
// Richardson extrapolation, E ≈ 2 E(2L) − E(L). The discs are drawn with
// their exact area fraction in the cells they cut.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>
#include <vector>

#include "wearscale/bem/half_space.hpp"
#include "wearscale/wear/energy_balance.hpp"
#include "wearscale/wear/two_contacts_3d.hpp"

using namespace wearscale;
using namespace wearscale::wear;

namespace {
constexpr double pi = std::numbers::pi;
constexpr double kYoung = 1.0, kNu = 0.3, kQ = 1e-3;  // Fig. 4.4: ν = 0.3
constexpr double kDx = 1.0;                              // grid spacing
constexpr double kD = 16.0;                              // disc diameter: 16 cells

// Fraction of the cell centred at (x, y) covered by the disc of diameter d at (cx, cy), 16 × 16 sub-samples
// in the cells its border crosses.
double coverage(double x, double y, double cx, double cy, double d) {
  const double r = 0.5 * d, h = 0.5 * kDx * std::sqrt(2.0), dist = std::hypot(x - cx, y - cy);
  if (dist <= r - h) return 1.0;
  if (dist >= r + h) return 0.0;
  constexpr int m = 16;
  int inside = 0;
  for (int a = 0; a < m; ++a)
    for (int b = 0; b < m; ++b) {
      const double sx = x + ((a + 0.5) / m - 0.5) * kDx, sy = y + ((b + 0.5) / m - 0.5) * kDx;
      inside += std::hypot(sx - cx, sy - cy) < r;
    }
  return static_cast<double>(inside) / (m * m);
}

// E_el = ½ ∫ p_x u_x dA (4.2) of uniform tractions q along x on discs at `centres` (offsets from the cell centre),
// on a periodic n × n cell.
double periodic_energy(std::size_t n, const std::vector<std::pair<double, double>>& centres, double d = kD) {
  const Grid2D grid = Grid2D::square(n, static_cast<double>(n) * kDx);
  bem::VectorField p(grid), u(grid);
  const double mid = 0.5 * grid.lx;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      double c = 0.0;
      for (const auto& [cx, cy] : centres) c += coverage(grid.x(i), grid.y(j), mid + cx, mid + cy, d);
      p.x(i, j) = kQ * c;
    }
  bem::HalfSpace half_space(grid, kYoung, kNu);
  half_space.displacement(p, u);
  return bem::HalfSpace::elastic_energy(p.x, u.x);
}

// The energy of the discs alone on an infinite half-space (Richardson on L, 2L).
double isolated_energy(std::size_t n, const std::vector<std::pair<double, double>>& centres, double d = kD) {
  FFTPlanCache::global().set_rigor(PlanRigor::Estimate);  // plan the large grids quickly
  const double e = 2.0 * periodic_energy(2 * n, centres, d) - periodic_energy(n, centres, d);
  FFTPlanCache::global().set_rigor(PlanRigor::Measure);  // back to the cache's default for other tests
  return e;
}

double shear_modulus() { return kYoung / (2.0 * (1.0 + kNu)); }

// Contacts a distance l apart, in line with the load (θ = 0) or across it (θ = π/2).
std::vector<std::pair<double, double>> pair_at(double l, bool across) {
  if (across) return {{0.0, -0.5 * l}, {0.0, 0.5 * l}};
  return {{-0.5 * l, 0.0}, {0.5 * l, 0.0}};
}

// Cells of 512 and 1024 points: 32 and 64 d, wide enough for pairs up to l = 4d.
constexpr std::size_t kCell = 512;
}  // namespace

TEST(TwoContactsBem, OneShearedDiscStoresTheClosedFormEnergy) {
  // (4.33) is exact for one disc; what remains after the extrapolation in L is the pixelated border, an
  // O((dx/d)²) error: 0.5 % with 16 cells across, about 4 times less with 32.
  const double g = shear_modulus();
  const double coarse = isolated_energy(256, {{0.0, 0.0}}, 16.0) / single_contact_elastic_energy(16.0, kQ, g, kNu) - 1;
  const double fine = isolated_energy(512, {{0.0, 0.0}}, 32.0) / single_contact_elastic_energy(32.0, kQ, g, kNu) - 1;
  std::printf("one disc vs (4.33): d = 16 dx %+.3e, d = 32 dx %+.3e, order %.2f, extrapolated %+.1e\n", coarse, fine,
              std::log2(coarse / fine), (4.0 * fine - coarse) / 3.0);
  EXPECT_LT(std::abs(coarse), 6e-3);
  EXPECT_LT(std::abs(fine), 2e-3);
  EXPECT_NEAR(std::log2(coarse / fine), 2.0, 0.3);
  EXPECT_LT(std::abs((4.0 * fine - coarse) / 3.0), 5e-4);  // extrapolated to dx → 0
}

TEST(TwoContactsBem, TwoDiscsInLineWithTheLoadStoreTheEnergyOf444) {
  // Fig. 4.4 (ν = 0.3, θ = 0): (4.44) is exact for l ≫ d and "still very accurate" at l = d. Measured: E_el,2
  // within 0.8 % of (4.44) from l = d on; its interaction term within 4.3 % at l = d, 0.3 % at l = 4d.
  const double g = shear_modulus();
  const double e1 = isolated_energy(kCell, {{0.0, 0.0}});
  double previous = 1.0;
  for (const double l_over_d : {1.0, 1.5, 2.0, 4.0}) {
    const double l = l_over_d * kD;
    const double e2 = isolated_energy(kCell, pair_at(l, false));
    const double e2_model = two_contact_elastic_energy(kD, l, 0.0, kQ, g, kNu);
    const double interaction = e2 - 2.0 * e1;  // the border errors of e1 and e2 cancel here
    const double interaction_model = e2_model - 2.0 * single_contact_elastic_energy(kD, kQ, g, kNu);
    const double error = interaction / interaction_model - 1.0;
    std::printf("θ = 0, l/d = %.1f: E_el,2 vs (4.44) %+.3e, interaction term %+.3e\n", l_over_d, e2 / e2_model - 1,
                error);
    EXPECT_NEAR(e2 / e2_model, 1.0, 0.01) << "l/d = " << l_over_d;
    EXPECT_LT(std::abs(error), 0.05) << "l/d = " << l_over_d;
    EXPECT_LT(std::abs(error), previous) << "l/d = " << l_over_d;  // exact as l/d grows
    previous = std::abs(error);
  }
  EXPECT_LT(previous, 5e-3);
}

TEST(TwoContactsBem, InteractionAcrossTheLoadIsWeakerByOneMinusNu) {
  // (4.44): the interaction ∝ 1 − ν sin²θ, so contacts side by side across the load (θ = π/2) interact 1 − ν
  // times as much as in line with it, for l ≫ d. Close up, (4.44) underestimates the interaction across the
  // load (measured: 16 % at l = d, 3 % at l = 2d, < 1 % at l = 4d).
  const double g = shear_modulus();
  const double e1 = isolated_energy(kCell, {{0.0, 0.0}});
  const double e1_model = single_contact_elastic_energy(kD, kQ, g, kNu);
  double previous = 1.0;
  for (const double l_over_d : {1.0, 2.0, 4.0}) {
    const double l = l_over_d * kD;
    const double across = isolated_energy(kCell, pair_at(l, true)) - 2.0 * e1;
    const double model = two_contact_elastic_energy(kD, l, pi / 2, kQ, g, kNu) - 2.0 * e1_model;
    std::printf("θ = π/2, l/d = %.1f: interaction term vs (4.44) %+.3e\n", l_over_d, across / model - 1);
    EXPECT_LT(std::abs(across / model - 1), 0.2) << "l/d = " << l_over_d;
    EXPECT_LT(std::abs(across / model - 1), previous) << "l/d = " << l_over_d;
    previous = std::abs(across / model - 1);
    if (l_over_d == 4.0) {
      const double along = isolated_energy(kCell, pair_at(l, false)) - 2.0 * e1;
      std::printf("interaction across/along at l = 4d: %.4f, (4.44): %.4f\n", across / along, 1.0 - kNu);
      EXPECT_NEAR(across / along, 1.0 - kNu, 0.01);
    }
  }
}
