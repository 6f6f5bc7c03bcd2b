// The 3D analytic wear map of two sheared circular micro-contacts (thesis §4.4–4.5, Fig. 4.6).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "wearscale/core/errors.hpp"
#include "wearscale/wear/analytic_wear_maps.hpp"
#include "wearscale/wear/energy_balance.hpp"
#include "wearscale/wear/two_contacts_3d.hpp"

using namespace wearscale;
using namespace wearscale::wear;

namespace {
constexpr double pi = std::numbers::pi;
constexpr double kGamma = 1.2, kG = 30e9, kSigma = 2e9;

// (4.48) with R = 1 written out from the thesis, independently of the library:
// d*/l = (C_n + (3π/8) C_inter x) x C_case, x = d/l.
double thesis_boundary(int region, double x, double c) {
  switch (region) {
    case 1: return (1.0 + 3.0 * pi / 8.0 * c * x) * x;                                  // one separated
    case 2: return (2.0 + 3.0 * pi / 8.0 * c * x) * x / 2.0;                            // two separated
    default: return (2.0 + 3.0 * pi / 8.0 * c * x) * x * x * x / ((1 + x) * (1 + x));  // combined, d_a = d + l
  }
}
}  // namespace

TEST(WearMap3D, InteractionConstantSpansOneThirdToTwoThirds) {
  // (4.49): most interaction 2/3 at ν = ½, θ = 0; least 1/3 at ν = ½, θ = π/2; always within [1/3, 2/3].
  EXPECT_NEAR(interaction_constant(0.5, 0.0), max_interaction_constant, 1e-15);
  EXPECT_NEAR(interaction_constant(0.5, pi / 2), min_interaction_constant, 1e-15);
  EXPECT_NEAR(interaction_constant(0.0, 1.0), 0.5, 1e-15);  // ν = 0: no dependence on θ
  for (double nu = -0.99; nu <= 0.5; nu += 0.01)
    for (double theta = 0.0; theta <= 2 * pi; theta += 0.05) {
      const double c = interaction_constant(nu, theta);
      ASSERT_GE(c, 1.0 / 3.0 - 1e-15) << nu << " " << theta;
      ASSERT_LE(c, 2.0 / 3.0 + 1e-15) << nu << " " << theta;
    }
}

TEST(WearMap3D, TwoContactEnergyIsBetweenTwoAndFourSingleContacts) {
  // (4.44): → 2 E_el,1 as l → ∞ (no interaction), and below 4 E_el,1 (one contact at 2q) even when adjacent:
  // E_el,2/E_el,1 = 2 + (3π/8) C_inter d/l.
  const double d = 1e-8, nu = 0.3;
  const double e1 = single_contact_elastic_energy(d, kSigma, kG, nu);
  EXPECT_NEAR(two_contact_elastic_energy(d, 1e6 * d, 0.0, kSigma, kG, nu) / e1, 2.0, 1e-5);
  for (double theta : {0.0, 0.7, pi / 2}) {
    const double adjacent = two_contact_elastic_energy(d, d, theta, kSigma, kG, nu) / e1;
    EXPECT_NEAR(adjacent, 2.0 + 3.0 * pi / 8.0 * interaction_constant(nu, theta), 1e-12);
    EXPECT_GT(adjacent, 2.0);
    EXPECT_LT(adjacent, 4.0);
  }
  // Interaction grows as the contacts approach (Fig. 4.4).
  EXPECT_GT(two_contact_elastic_energy(d, 1.5 * d, 0.0, kSigma, kG, nu),
            two_contact_elastic_energy(d, 3.0 * d, 0.0, kSigma, kG, nu));
}

TEST(WearMap3D, EnergyRatioFormulaEqualsTheRatioOfTheEnergies) {
  // (4.48) with d* (4.35) and C_inter (4.49) against ΔE_el ((4.44), (4.33)) over E_ad ((4.45)–(4.47)).
  for (const double nu : {-0.2, 0.0, 0.3, 0.5})
    for (const double theta : {0.0, 0.4, pi / 2, 2.5})
      for (const double l_over_d : {1.0, 1.3, 2.0, 5.0}) {
        const double d_star = critical_diameter(kGamma, kG, nu, kSigma);
        const double d = 0.8 * d_star, l = l_over_d * d;
        const double c = interaction_constant(nu, theta);
        for (const ParticleCase k : particle_cases) {
          const double direct = energy_ratio_from_energies(k, d, l, theta, kSigma, kG, nu, kGamma);
          EXPECT_NEAR(energy_ratio_3d(k, d / l, d_star / l, c) / direct, 1.0, 1e-12)
              << name(k) << " ν = " << nu << " θ = " << theta << " l/d = " << l_over_d;
        }
      }
}

TEST(WearMap3D, CasesHaveTheConstantsOfTheThesis) {
  EXPECT_EQ(count_constant(ParticleCase::OneSeparated), 1.0);
  EXPECT_EQ(count_constant(ParticleCase::TwoSeparated), 2.0);
  EXPECT_EQ(count_constant(ParticleCase::Combined), 2.0);
  EXPECT_EQ(case_constant(ParticleCase::OneSeparated, 0.5), 1.0);
  EXPECT_EQ(case_constant(ParticleCase::TwoSeparated, 0.5), 0.5);
  EXPECT_NEAR(case_constant(ParticleCase::Combined, 0.5), 1.0 / 9.0, 1e-15);  // d = l/2: d_a = 3d
}

TEST(WearMap3D, EnergyRatioIsOneOnTheBoundaryAndRegionsSwitchThere) {
  for (const double c : {min_interaction_constant, 0.5, max_interaction_constant})
    for (double x = 0.05; x <= 1.0; x += 0.05) {
      for (const ParticleCase k : particle_cases) {
        const double b = boundary_dstar_over_l(k, x, c);
        EXPECT_NEAR(b, thesis_boundary(static_cast<int>(k) + 1, x, c), 1e-14 * b);
        EXPECT_NEAR(energy_ratio_3d(k, x, b, c), 1.0, 1e-15);
      }
      // Each boundary is inclusive: on it the case is feasible, just above it not.
      const double b2 = boundary_dstar_over_l(ParticleCase::TwoSeparated, x, c);
      EXPECT_EQ(classify_3d(x, b2, c), Region3D::TwoSeparated);
      EXPECT_EQ(classify_3d(x, std::nextafter(b2, 10.0), c), Region3D::OneSeparated);
      const double b1 = boundary_dstar_over_l(ParticleCase::OneSeparated, x, c);
      EXPECT_EQ(classify_3d(x, b1, c), Region3D::OneSeparated);
      EXPECT_EQ(classify_3d(x, std::nextafter(b1, 10.0), c), Region3D::Plastic);
      const double bc = boundary_dstar_over_l(ParticleCase::Combined, x, c);
      EXPECT_EQ(classify_3d(x, bc, c), Region3D::Combined);
      EXPECT_EQ(classify_3d(x, std::nextafter(bc, 10.0), c), Region3D::TwoSeparated);
    }
}

TEST(WearMap3D, SampledMapReproducesTheBoundaryLinesAtEverySamplePoint) {
  for (const double c : {max_interaction_constant, min_interaction_constant}) {
    const WearMap map = analytic_map_3d(default_d_over_l_axis(), default_dstar_over_l_axis(), c);
    ASSERT_EQ(map.region.size(), 201u * 201u);
    for (std::size_t i = 0; i < map.x.n; ++i)
      for (std::size_t j = 0; j < map.y.n; ++j) {
        const double x = map.x.value(i), y = map.y.value(j);
        const int code = map.region[map.index(i, j)];
        // A case is feasible (R ≥ 1) at or below its line; the region is the most severe feasible case.
        for (int r = 1; r <= 3; ++r)
          ASSERT_EQ(code >= r, y <= thesis_boundary(r, x, c)) << "region " << r << " at d/l = " << x
                                                               << ", d*/l = " << y << ", C_inter = " << c;
        EXPECT_EQ(map.layer("R_one_separated").values[map.index(i, j)] >= 1.0, code >= 1);
      }
    for (int code = 0; code <= 3; ++code) EXPECT_GT(map.count(code), 500u) << code;
  }
}

TEST(WearMap3D, FeasibleCasesAreNestedAndInteractionFavoursWear) {
  const WearMap most = analytic_map_3d(default_d_over_l_axis(), default_dstar_over_l_axis(), max_interaction_constant);
  const WearMap least = analytic_map_3d(default_d_over_l_axis(), default_dstar_over_l_axis(), min_interaction_constant);
  const auto& r1 = most.layer("R_one_separated").values;
  const auto& r2 = most.layer("R_two_separated").values;
  const auto& rc = most.layer("R_combined").values;
  for (std::size_t k = 0; k < r1.size(); ++k) {
    ASSERT_LT(rc[k], r2[k]) << k;  // R_comb/R_2sep = 2d²/(d+l)² < 1 for d ≤ l
    ASSERT_LT(r2[k], r1[k]) << k;
    ASSERT_GE(most.region[k], least.region[k]) << k;  // "increasing elastic interactions favors wear particle formation"
  }
  for (int code = 1; code <= 3; ++code) {
    std::size_t at_least_most = 0, at_least_least = 0;
    for (std::size_t k = 0; k < r1.size(); ++k) {
      at_least_most += most.region[k] >= code;
      at_least_least += least.region[k] >= code;
    }
    EXPECT_GT(at_least_most, at_least_least) << code;
  }
}

TEST(WearMap3D, InteractingContactsSmallerThanTheCriticalSizeCanStillDetach) {
  // Fig. 4.6: below the line d = d* a single contact is plastic, yet two adjacent ones (d = l) at d*/l = 1.2
  // (d = 0.83 d*) can form two particles at most interaction ((2 + π/4)/2 = 1.39 ≥ 1.2), and one at least
  // interaction (1 + π/8 = 1.39 ≥ 1.2 > (2 + π/8)/2 = 1.196).
  EXPECT_EQ(classify_3d(1.0, 1.2, max_interaction_constant), Region3D::TwoSeparated);
  EXPECT_EQ(classify_3d(1.0, 1.2, min_interaction_constant), Region3D::OneSeparated);
  // On the line d = d* one particle is always possible: R_1sep = 1 + (3π/8) C_inter d/l ≥ 1.
  for (double x = 0.1; x <= 1.0; x += 0.1) EXPECT_GE(classify_3d(x, x, min_interaction_constant), Region3D::OneSeparated);
  // Far apart contacts (d/l → 0) behave as single ones: plastic above d = d*.
  EXPECT_EQ(classify_3d(0.01, 0.0101, max_interaction_constant), Region3D::Plastic);
}

TEST(WearMap3D, RefusesPointsAndParametersOutsideTheModel) {
  EXPECT_THROW(energy_ratio_3d(ParticleCase::Combined, 1.2, 1.0, 0.5), InputError);  // overlapping contacts
  EXPECT_THROW(classify_3d(0.5, 0.0, 0.5), InputError);
  EXPECT_THROW(interaction_constant(0.6, 0.0), InputError);
  EXPECT_THROW(two_contact_elastic_energy(2.0, 1.0, 0.0, kSigma, kG, 0.3), InputError);
  MapAxis wide = default_d_over_l_axis();
  wide.max = 1.5;
  EXPECT_THROW(analytic_map_3d(wide, default_dstar_over_l_axis(), 0.5), InputError);
  EXPECT_THROW(analytic_map_3d(default_d_over_l_axis(), default_dstar_over_l_axis(), 0.9), InputError);
}
