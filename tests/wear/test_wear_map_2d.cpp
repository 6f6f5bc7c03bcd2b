// The 2D analytic wear map of N sheared micro-contacts (thesis ch. 3, Fig. 3.7).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "wearscale/core/errors.hpp"
#include "wearscale/wear/analytic_wear_maps.hpp"
#include "wearscale/wear/micro_contacts_2d.hpp"

using namespace wearscale;
using namespace wearscale::wear;

namespace {
// A brittle model material in SI units; B = 1 m, 𝓜 = 20 (a finite medium).
constexpr double kE = 70e9, kNu = 0.25, kGamma = 1.5, kQ = 3e9, kB = 1.0, kM = 20.0;
}  // namespace

TEST(WearMap2D, EnergyRatiosOfTheEnergiesAreTheSizeRatiosOfTheMap) {
  // R_sep = E_el,Nq/E_ad,sep (3.15)/(3.17) = d_r/d* (3.24) and R_comb = E_el,Nq/E_ad,comb (3.20) = d_r²/(d_a d*)
  // (3.26), with d* from (3.23): every material parameter goes into d*.
  const double d_star = critical_size_2d(kGamma, kE, kNu, kQ, kM);
  for (const MicroContactRow row : {MicroContactRow{1, 0.7 * d_star, 0.0}, MicroContactRow{3, 0.4 * d_star, 0.2 * d_star},
                                    MicroContactRow{5, 1.3 * d_star, 2.0 * d_star}}) {
    const double e_el = row_elastic_energy_2d(row, kQ, kE, kNu, kB, kM);
    const double dr = row.real_size(), da = row.apparent_size();
    EXPECT_NEAR(e_el / adhesive_energy_2d(dr, kGamma, kB) / separated_ratio_2d(dr, d_star), 1.0, 1e-12);
    EXPECT_NEAR(e_el / adhesive_energy_2d(da, kGamma, kB) / combined_ratio_2d(dr, da, d_star), 1.0, 1e-12);
  }
}

TEST(WearMap2D, TheEnergyOfNInteractingLoadsIsThatOfOneLoadNTimesLarger) {
  // (3.9)–(3.11): E_el,Nq = N² E_el,1q, whatever the spacing (finite next to the medium), and (3.14): one load q
  // over d is a point load Q = q d, so N contacts of d store what one contact of N d stores.
  const MicroContactRow one{1, 2e-9, 0.0}, four{4, 2e-9, 7e-9}, wide{1, 8e-9, 0.0};
  const double e1 = row_elastic_energy_2d(one, kQ, kE, kNu, kB, kM);
  EXPECT_NEAR(row_elastic_energy_2d(four, kQ, kE, kNu, kB, kM) / e1, 16.0, 1e-12);
  EXPECT_NEAR(row_elastic_energy_2d(four, kQ, kE, kNu, kB, kM) / row_elastic_energy_2d(wide, kQ, kE, kNu, kB, kM), 1.0,
              1e-12);
}

TEST(WearMap2D, RegionsChangeExactlyOnTheLinesOfTheThesis) {
  // d* = 1. Separated iff d_r ≥ d* (3.25): inclusive on the line.
  EXPECT_EQ(classify_2d(1.0, 1.5, 1.0), Region2D::Separated);
  EXPECT_EQ(classify_2d(std::nextafter(1.0, 0.0), 1.5, 1.0), Region2D::Plastic);
  // Combined iff d_a ≤ d_r²/d* (3.27): d_r = 2 puts the line at d_a = 4 exactly.
  EXPECT_EQ(classify_2d(2.0, 4.0, 1.0), Region2D::Combined);
  EXPECT_EQ(classify_2d(2.0, std::nextafter(4.0, 5.0), 1.0), Region2D::Separated);
  // A single contact (d_a = d_r) at d* can detach as one particle; d_a < d_r is no row of contacts.
  EXPECT_EQ(classify_2d(1.0, 1.0, 1.0), Region2D::Combined);
  EXPECT_EQ(classify_2d(2.0, std::nextafter(2.0, 0.0), 1.0), Region2D::Inaccessible);
  // The lines scale with d*.
  EXPECT_EQ(classify_2d(6.0, 12.0, 3.0), Region2D::Combined);
  EXPECT_EQ(classify_2d(6.0, std::nextafter(12.0, 13.0), 3.0), Region2D::Separated);
}

TEST(WearMap2D, ContactsSmallerThanTheCriticalSizeDetachTogetherWhenCloseEnough) {
  // Only the real contact size d_r matters for detachment (§3.1.3, "Partial contact"): three contacts of d*/2
  // (d_r = 1.5 d*) form one particle if d_a ≤ 2.25 d*, i.e. gaps λ ≤ 0.375 d*, else separate particles.
  const double d_star = 1.0;
  const MicroContactRow close{3, 0.5, 0.3}, apart{3, 0.5, 0.45}, single{1, 0.5, 0.0};
  EXPECT_EQ(classify_2d(close.real_size(), close.apparent_size(), d_star), Region2D::Combined);
  EXPECT_EQ(classify_2d(apart.real_size(), apart.apparent_size(), d_star), Region2D::Separated);
  EXPECT_EQ(classify_2d(single.real_size(), single.apparent_size(), d_star), Region2D::Plastic);
  // κ criterion (3.29) on the same rows: κ ≥ √(d*/d_a) exactly when combined.
  EXPECT_GE(contact_fraction(close.real_size(), close.apparent_size()),
            minimum_contact_fraction(close.apparent_size(), d_star));
  EXPECT_LT(contact_fraction(apart.real_size(), apart.apparent_size()),
            minimum_contact_fraction(apart.apparent_size(), d_star));
}

TEST(WearMap2D, SampledMapReproducesTheBoundaryLinesAtEverySamplePoint) {
  const WearMap map = analytic_map_2d(default_real_size_axis(), default_apparent_size_axis());
  ASSERT_EQ(map.region.size(), 301u * 301u);
  std::size_t checked = 0;
  for (std::size_t i = 0; i < map.x.n; ++i)
    for (std::size_t j = 0; j < map.y.n; ++j) {
      const double dr = map.x.value(i), da = map.y.value(j);
      // VERIFICATION.md, with d* = 1: separated iff d_r ≥ d*, combined iff d_a ≤ d_r²/d*, d_a ≥ d_r accessible.
      const int expected = da < dr ? -1 : dr < 1.0 ? 0 : da <= dr * dr ? 2 : 1;
      ASSERT_EQ(map.region[map.index(i, j)], expected) << "d_r/d* = " << dr << ", d_a/d* = " << da;
      ++checked;
    }
  EXPECT_EQ(checked, map.region.size());
  // Every region is present on the default map (Fig. 3.7).
  for (int code : {-1, 0, 1, 2}) EXPECT_GT(map.count(code), 1000u) << code;
}

TEST(WearMap2D, KappaCriterionAgreesWithTheCombinedRegion) {
  // (3.29) is (3.27) rewritten: κ ≥ √(d*/d_a) ⇔ d_a ≤ d_r²/d*, at every accessible point with d_a ≥ d* (3.30).
  const WearMap map = analytic_map_2d(default_real_size_axis(), default_apparent_size_axis());
  const auto& kappa = map.layer("kappa").values;
  const auto& kappa_min = map.layer("kappa_min").values;
  const auto& r_comb = map.layer("R_comb").values;
  std::size_t compared = 0;
  for (std::size_t k = 0; k < map.region.size(); ++k) {
    if (map.region[k] < 0 || std::abs(r_comb[k] - 1.0) < 1e-9) continue;  // inaccessible, or a rounding tie
    if (map.y.value(k % map.y.n) < 1.0) continue;                       // (3.30)
    EXPECT_EQ(kappa[k] >= kappa_min[k], map.region[k] == 2) << k;
    EXPECT_EQ(r_comb[k] >= 1.0, map.region[k] == 2) << k;
    ++compared;
  }
  EXPECT_GT(compared, 30000u);
}

TEST(WearMap2D, CombinedParticlesAreNeverEasierThanSeparatedOnes) {
  // R_sep ≥ R_comb everywhere (§3.1.3, limits of the criterion): d_a ≥ d_r.
  const WearMap map = analytic_map_2d(default_real_size_axis(), default_apparent_size_axis());
  const auto& r_sep = map.layer("R_sep").values;
  const auto& r_comb = map.layer("R_comb").values;
  for (std::size_t k = 0; k < map.region.size(); ++k)
    if (map.region[k] >= 0) {
      ASSERT_GE(r_sep[k], r_comb[k]) << k;
    }
}

TEST(WearMap2D, RefusesNonPhysicalInput) {
  EXPECT_THROW(classify_2d(-1.0, 2.0, 1.0), InputError);
  EXPECT_THROW(classify_2d(1.0, 2.0, 0.0), InputError);
  EXPECT_THROW(critical_size_2d(kGamma, kE, 0.6, kQ, kM), InputError);
  EXPECT_THROW(critical_size_2d(kGamma, kE, kNu, kQ, 0.0), InputError);
  EXPECT_THROW(check(MicroContactRow{0, 1.0, 0.0}), InputError);
  EXPECT_THROW(check(MicroContactRow{2, 1.0, -0.5}), InputError);
  MapAxis bad = default_real_size_axis();
  bad.min = -1.0;
  try {
    analytic_map_2d(bad, default_apparent_size_axis());
    FAIL() << "a negative d_r/d* axis was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("d_r/d*"), std::string::npos) << e.what();
  }
}
