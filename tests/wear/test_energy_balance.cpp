// The energy balance of a single sheared micro-contact (§4.3).
#include <gtest/gtest.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/wear/energy_balance.hpp"

using namespace wearscale;
using namespace wearscale::wear;

namespace {
constexpr double kGamma = 1.2, kG = 30e9, kNu = 0.3, kSigma = 2e9;
}

TEST(EnergyBalance, AContactOfTheCriticalDiameterReleasesExactlyTheAdhesiveEnergy) {
  const double d = critical_diameter(kGamma, kG, kNu, kSigma);
  EXPECT_NEAR(single_contact_elastic_energy(d, kSigma, kG, kNu) / adhesive_energy(d, kGamma), 1.0, 1e-12);  // (4.18)
}

TEST(EnergyBalance, LargerContactsDetachSmallerOnesDoNot) {
  const double d = critical_diameter(kGamma, kG, kNu, kSigma);
  // R ∝ d (4.34): twice d* gives R = 2, half gives ½.
  EXPECT_NEAR(single_contact_elastic_energy(2 * d, kSigma, kG, kNu) / adhesive_energy(2 * d, kGamma), 2.0, 1e-12);
  EXPECT_NEAR(single_contact_elastic_energy(d / 2, kSigma, kG, kNu) / adhesive_energy(d / 2, kGamma), 0.5, 1e-12);
}

TEST(EnergyBalance, StrongerJunctionsMakeSmallerCriticalParticles) {
  // d* ∝ 1/σ_j² (4.35), the size effect of Aghababaei et al. (1.13).
  EXPECT_NEAR(critical_diameter(kGamma, kG, kNu, kSigma) / critical_diameter(kGamma, kG, kNu, 2 * kSigma), 4.0, 1e-12);
}

TEST(EnergyBalance, RefusesNonPhysicalMaterials) {
  EXPECT_THROW(critical_diameter(0.0, kG, kNu, kSigma), InputError);
  EXPECT_THROW(critical_diameter(kGamma, kG, 0.6, kSigma), InputError);
  EXPECT_THROW(critical_diameter(kGamma, kG, kNu, -1.0), InputError);
}
