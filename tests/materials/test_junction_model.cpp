// The scale-linking model (§7.1.2, §9.3.2) on the thesis' strength laws
// (Fig. 9.18) reproduces the numbers of VERIFICATION.md.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "wearscale/core/errors.hpp"
#include "wearscale/io/shipped_data.hpp"
#include "wearscale/materials/junction_model.hpp"
#include "wearscale/materials/material.hpp"

using namespace wearscale;
using namespace wearscale::materials;

namespace {
const StrengthLaw si(shipped_table("thesis", "Si"));
const StrengthLaw sio2(shipped_table("thesis", "SiO2"));
}  // namespace

TEST(StrengthLaw, FollowsTheSimplifiedLawsOfFig918) {
  EXPECT_DOUBLE_EQ(si.sigma_max(12e9), 10.6e9);
  EXPECT_DOUBLE_EQ(si.sigma_max(19.999e9), 10.6e9);
  EXPECT_DOUBLE_EQ(si.sigma_max(20e9), 4.0e9);  // the jump: 4 GPa at and above 20 GPa
  EXPECT_DOUBLE_EQ(si.sigma_dyn(25e9), 1.8e9);
  EXPECT_NEAR(sio2.sigma_max(30e9), 8.5e9 + 0.096 * 10e9, 1e3);
  EXPECT_NEAR(sio2.sigma_dyn(8.5e9), 6.3e9 + 0.096 * 8.5e9, 1e3);
  EXPECT_EQ(si.jumps(), std::vector<double>{20e9});
}

TEST(StrengthLaw, RefusesPressuresOutsideItsTableUnlessToldToClamp) {
  EXPECT_THROW(si.sigma_max(31e9), NumericalError);
  EXPECT_THROW(si.sigma_max(-1.0), NumericalError);
  const StrengthLaw clamped(shipped_table("thesis", "Si"), OutsideTable::Clamp);
  EXPECT_DOUBLE_EQ(clamped.sigma_max(100e9), 4.0e9);
}

TEST(JunctionModel, CriticalPressuresAre106And85GPa) {
  EXPECT_NEAR(critical_pressure(si), 10.6e9, 1e3);
  EXPECT_NEAR(critical_pressure(sio2), 8.5e9, 1e3);
}

TEST(JunctionModel, FrictionCoefficientsAre014And084) {
  EXPECT_NEAR(friction_coefficient(si, critical_pressure(si)), 0.14, 0.005);      // (9.14)
  EXPECT_NEAR(friction_coefficient(sio2, critical_pressure(sio2)), 0.84, 0.005);  // (9.15)
}

TEST(JunctionModel, SteadySlopesAre057And071) {
  const double e_star = effective_modulus(silica(), silica());  // 37.6 GPa: both bodies SiO2
  EXPECT_NEAR(steady_slope_rms(critical_pressure(sio2), e_star), 0.57, 0.005);
  EXPECT_NEAR(steady_slope_rms(critical_pressure(si), e_star), 0.71, 0.005);
}

TEST(JunctionModel, ContactRatioAndWearRateAreTheLoadOverTheCriticalPressure) {
  const double p_crit = critical_pressure(sio2);
  EXPECT_DOUBLE_EQ(minimum_contact_ratio(312e6, p_crit), 312e6 / p_crit);  // (7.6)
  EXPECT_DOUBLE_EQ(wear_rate(312e6, p_crit), 312e6 / p_crit);              // (9.21)
}

TEST(JunctionModel, DemFitOfFig73) {
  // σ_m,T = 7.5 GPa, independent of pressure (7.11), (7.12): p_T = (A/A0)·7.5 GPa, p_T,min = p_N.
  const auto law = StrengthLaw::constant("SiO2-DEM", 7.5e9, 100e9, "Fig. 7.2 fit");
  const double p_crit = critical_pressure(law);
  EXPECT_NEAR(p_crit, 7.5e9, 1e3);
  for (double ratio : {0.2, 0.5, 1.0})
    EXPECT_NEAR(tangential_resistance(law, 1e9, ratio), ratio * 7.5e9, 1e-3);
  for (double p_n : {0.5e9, 2e9, 6e9}) EXPECT_NEAR(minimum_tangential_resistance(law, p_n, p_crit), p_n, 1e-3);
}

TEST(JunctionModel, ResistanceAtTheMinimumContactRatioIsTheMinimum) {
  // (7.9) at A/A0 = p_N/p_crit gives (7.10): the local pressure is then p_crit.
  const double p_crit = critical_pressure(sio2), p_n = 1e9;
  EXPECT_NEAR(tangential_resistance(sio2, p_n, minimum_contact_ratio(p_n, p_crit)),
              minimum_tangential_resistance(sio2, p_n, p_crit), 1e-3);
}

// The table falls short of p_crit: bad input naming it (exit 2), not a numerical failure.
TEST(JunctionModel, ATableThatNeverCrushesIsBadInputNamingTheTable) {
  const auto strong = StrengthLaw::constant("strong", 80e9, 50e9, "test");
  try {
    critical_pressure(strong);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("σ_max(p) > p up to the end of the table"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("extend it"));
  }
}

TEST(InterfaceLaw, SilicaOnSilicaSlidesAt084AndSilicaOnSiliconAt014) {
  const auto same = interface_law("SiO2", sio2, "SiO2", sio2);
  EXPECT_NEAR(same.mu0, 0.84, 0.005);
  EXPECT_NEAR(same.p_crit, 8.5e9, 1e3);
  const auto mixed = interface_law("SiO2", sio2, "Si", si);  // Si beneath the interface gives way
  EXPECT_EQ(mixed.governing, "Si");
  EXPECT_NEAR(mixed.mu0, 0.14, 0.005);
  EXPECT_NEAR(mixed.p_crit, 10.6e9, 1e3);
  EXPECT_DOUBLE_EQ(mixed.contact_ratio(20e9), 1.0);  // beyond p_crit: full contact
  EXPECT_DOUBLE_EQ(mixed.wear_rate(1.06e9), 0.1);
}
