// The cohesive pair force of §6.1 and its parameters (6.49)-(6.62).
#include <cmath>
#include <gsl/gsl_integration.h>
#include <gtest/gtest.h>
#include <numbers>

#include "input_error_of.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/dem/cohesive_law.hpp"
#include "wearscale/dem/particles.hpp"
#include "wearscale/materials/material.hpp"
#include "pair_setup.hpp"

using namespace wearscale;
using namespace wearscale::dem;
using wearscale::dem::test_support::sphere_mass;

namespace {

// Table 6.4: the patch-test targets (no units).
CohesiveMaterial table_6_4(double poisson = 0.15, double s = 0.5) {
  auto m = patch_test_targets();
  m.poisson = poisson;
  m.scaling_exponent = s;
  return m;
}

// ∫_0^δf F_N dδ by GSL adaptive quadrature with the kink at δ_e as a break point.
double fracture_work(const CohesivePair& p) {
  gsl_integration_workspace* w = gsl_integration_workspace_alloc(100);
  gsl_function f;
  f.function = [](double x, void* params) { return normal_force(*static_cast<const CohesivePair*>(params), x); };
  f.params = const_cast<CohesivePair*>(&p);
  double points[3] = {0.0, p.delta_e, p.delta_f};
  const std::size_t npts = p.delta_e < p.delta_f ? 3 : 2;
  if (npts == 2) points[1] = p.delta_f;
  double result = 0.0, error = 0.0;
  gsl_integration_qagp(&f, points, npts, 0.0, 1e-12, 100, w, &result, &error);
  gsl_integration_workspace_free(w);
  return result;
}

}  // namespace

TEST(CohesiveParameters, PatchTestTargetsGiveDminThirtyAndDcOneHundredFifty) {
  const auto m = table_6_4();
  EXPECT_NEAR(minimum_diameter(m), 30.0, 1e-12);    // (6.62), §6.2
  EXPECT_NEAR(critical_diameter(m), 150.0, 1e-12);  // (6.35), §6.2
}

TEST(CohesiveParameters, AmorphousSilicaGivesThesisSizes) {
  const auto m = cohesive_material(materials::silica(), 0.5);
  EXPECT_NEAR(minimum_diameter(m), 0.37e-9, 0.01e-9);  // §6.3: d_min = 0.37 nm
  EXPECT_NEAR(critical_diameter(m), 1.7e-9, 0.02e-9);  // §6.3: d_c = 1.7 nm
  EXPECT_NEAR(materials::critical_size(materials::silica(), m.shear_strength,
                                       materials::JunctionGeometry::DemCylinder),
              18e-9, 0.6e-9);  // (6.65): d* ≈ 18 nm
  EXPECT_DOUBLE_EQ(m.restitution, 0.9);  // Table 6.5
}

TEST(CohesiveParameters, StiffnessesInvertTheHcpElasticConstants) {
  // (6.49)-(6.50) invert C11 = √2(3k_N + 2k_T)/(5r), C12 = √2(k_N − k_T)/(5r) (6.47)-(6.48)
  // of an isotropic solid with E, ν.
  for (double nu : {0.0, 0.1, 0.15, 0.25}) {
    const auto m = table_6_4(nu);
    const double r = 10.0;
    const auto p = cohesive_pair(m, r, r, 1.0, 1.0);
    const double c11 = std::numbers::sqrt2 / (5.0 * r) * (3.0 * p.k_n + 2.0 * p.k_t);
    const double c12 = std::numbers::sqrt2 / (5.0 * r) * (p.k_n - p.k_t);
    const double lame = m.young * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    const double shear = m.young / (2.0 * (1.0 + nu));
    EXPECT_NEAR(c11, lame + 2.0 * shear, 1e-12) << "ν = " << nu;
    EXPECT_NEAR(c12, lame, 1e-12) << "ν = " << nu;
  }
}

TEST(CohesiveParameters, PoissonRatioAboveOneQuarterIsRefusedWithTheReason) {
  const auto message = input_error_of([] { CohesiveLaw law({table_6_4(0.3)}); });
  EXPECT_NE(message.find("0.3"), std::string::npos) << message;
  EXPECT_NE(message.find("0.25"), std::string::npos) << message;
  EXPECT_NE(message.find("pair force"), std::string::npos) << message;
  EXPECT_NO_THROW(CohesiveLaw({table_6_4(0.25)}));
}

TEST(CohesiveParameters, RestitutionIsRequired) {
  auto si = materials::silicon();
  si.restitution.reset();
  EXPECT_THROW(cohesive_material(si, 0.5), InputError);
  EXPECT_DOUBLE_EQ(cohesive_material(si, 0.5, 0.8).restitution, 0.8);
}

TEST(CohesiveForce, FollowsTheThreeBranchesOfEquation6_3) {
  const auto m = table_6_4();
  const auto p = cohesive_pair(m, 20.0, 20.0, 1.0, 1.0);  // r_i + r_j = 40 < d_c
  ASSERT_LT(p.delta_e, p.delta_f);
  EXPECT_NEAR(p.delta_e, 40.0 * 0.2 / 1.0, 1e-12);   // (6.56)
  EXPECT_NEAR(p.delta_f, 4.0 * 1.5 / 0.2, 1e-12);    // (6.57), first case
  EXPECT_DOUBLE_EQ(normal_force(p, -0.5), -0.5 * p.k_n);  // repulsion
  EXPECT_DOUBLE_EQ(normal_force(p, 0.3 * p.delta_e), 0.3 * p.delta_e * p.k_n);  // cohesion
  EXPECT_NEAR(normal_force(p, p.delta_e), p.k_n * p.delta_e, 1e-12);  // peak = A_N σ_m,N
  EXPECT_NEAR(normal_force(p, p.delta_e), normal_cross_section(20.0, 0.15) * 0.2, 1e-12);
  const double mid = 0.5 * (p.delta_e + p.delta_f);
  EXPECT_NEAR(normal_force(p, mid), 0.5 * p.k_n * p.delta_e, 1e-12);  // softening, halfway
  EXPECT_DOUBLE_EQ(normal_force(p, p.delta_f), 0.0);
  EXPECT_DOUBLE_EQ(normal_force(p, 1.01 * p.delta_f), 0.0);
}

TEST(CohesiveForce, TangentialCapFallsLinearlyToZeroAtFracture) {
  const auto p = cohesive_pair(table_6_4(), 20.0, 20.0, 1.0, 1.0);
  EXPECT_DOUBLE_EQ(tangential_cap(p, -1.0), p.f_mt);  // (6.5): overlapping
  EXPECT_DOUBLE_EQ(tangential_cap(p, 0.0), p.f_mt);
  EXPECT_NEAR(tangential_cap(p, 0.25 * p.delta_f), 0.75 * p.f_mt, 1e-12);
  EXPECT_NEAR(tangential_cap(p, p.delta_f), 0.0, 1e-12);
  EXPECT_NEAR(p.f_mt, tangential_cross_section(20.0, 0.15) * 0.1, 1e-12);  // (6.58)
}

TEST(CohesiveForce, FractureEnergyIsTwiceGammaTimesTheCrossSection) {
  const auto m = table_6_4();
  for (double r : {10.0, 40.0, 70.0}) {  // r_i + r_j ≤ d_c = 150
    const auto p = cohesive_pair(m, r, r, 1.0, 1.0);
    EXPECT_NEAR(fracture_work(p), 2.0 * m.surface_energy * normal_cross_section(r, m.poisson),
                1e-9 * fracture_work(p))
        << "r = " << r;  // (6.18)-(6.20)
  }
  // Above d_c with s = ½ the rescaled δ_f keeps the fracture energy (Fig. 6.5);
  // the matched strength drops as ((r_i + r_j)/d_c)^(−½) (6.63).
  for (double r : {100.0, 300.0, 1000.0}) {
    const auto p = cohesive_pair(m, r, r, 1.0, 1.0);
    EXPECT_NEAR(fracture_work(p), 2.0 * m.surface_energy * normal_cross_section(r, m.poisson),
                1e-9 * fracture_work(p))
        << "r = " << r;
    const double strength = normal_force(p, p.delta_f) / normal_cross_section(r, m.poisson);
    EXPECT_NEAR(strength, 0.2 * std::pow(2.0 * r / 150.0, -0.5), 1e-12) << "r = " << r;
  }
  // With s = 0 the strength is kept instead and the fracture energy grows.
  const auto p0 = cohesive_pair(table_6_4(0.15, 0.0), 300.0, 300.0, 1.0, 1.0);
  EXPECT_NEAR(normal_force(p0, p0.delta_f) / normal_cross_section(300.0, 0.15), 0.2, 1e-12);
  EXPECT_GT(fracture_work(p0), 2.0 * 1.5 * normal_cross_section(300.0, 0.15));
}

TEST(CohesiveForce, EnergyIsTheIntegralOfTheForce) {
  const auto p = cohesive_pair(table_6_4(), 20.0, 20.0, 1.0, 1.0);
  // Sample points away from the kinks at δ_e and δ_f, where a central difference is O(h).
  for (double d : {-2.0, 0.0, 0.5 * p.delta_e, 0.999 * p.delta_e, 0.5 * (p.delta_e + p.delta_f), 0.99 * p.delta_f}) {
    const double h = 1e-6;
    const double slope = (normal_energy(p, d + h) - normal_energy(p, d - h)) / (2.0 * h);
    EXPECT_NEAR(slope, normal_force(p, d), 1e-7 * p.k_n * p.delta_e) << "δ = " << d;
  }
  EXPECT_NEAR(normal_energy(p, 0.0), -0.5 * p.k_n * p.delta_e * p.delta_f, 1e-12);  // −2γA_N
}

TEST(CohesiveForce, DampingGivesTheRestitutionCoefficientInTheSmallDampingLimit) {
  const auto m = table_6_4();
  const double r = 20.0, mass = sphere_mass(r, m.density);
  const auto p = cohesive_pair(m, r, r, mass, mass);
  const double m_eff = 0.5 * mass;
  EXPECT_NEAR(p.c_n, 2.0 * (1.0 - 0.95) / std::numbers::pi * std::sqrt(p.k_n * m_eff), 1e-12);  // (6.59)
  EXPECT_NEAR(p.c_t, 2.0 * (1.0 - 0.95) / std::numbers::pi * std::sqrt(p.k_t * m_eff), 1e-12);  // (6.60)
  EXPECT_NEAR(critical_time_step(mass, p.k_n), std::sqrt(2.0 * mass / p.k_n), 1e-12);  // (6.6)
}

TEST(CohesiveForce, MixedPairsUseTheWeakerStrengthAndSeriesStiffness) {
  auto a = table_6_4();
  auto b = table_6_4();
  b.name = "stiff";
  b.young = 3.0;
  b.tensile_strength = 0.1;
  const auto ab = mix(a, b);
  EXPECT_DOUBLE_EQ(ab.young, 1.5);
  EXPECT_DOUBLE_EQ(ab.tensile_strength, 0.1);
  EXPECT_DOUBLE_EQ(mix(a, a).young, a.young);
}

TEST(CohesiveForce, AnInterfaceStatedOnItsOwnReplacesTheMixForPairsAcrossItOnly) {
  auto a = table_6_4();
  auto b = table_6_4();
  b.name = "stiff";
  b.young = 3.0;
  auto interface = mix(a, b);
  interface.surface_energy = 0.3;  // a fifth of both materials' γ
  CohesiveLaw law({a, b});
  law.set_interface(1, 0, interface);
  EXPECT_DOUBLE_EQ(law.pair_material(0, 1).surface_energy, 0.3);
  EXPECT_DOUBLE_EQ(law.pair_material(1, 0).surface_energy, 0.3);
  EXPECT_DOUBLE_EQ(law.pair_material(0, 0).surface_energy, 1.5);
  EXPECT_DOUBLE_EQ(law.pair_material(1, 1).surface_energy, 1.5);

  // Two spheres across the interface separate with 2 γ_ab A_N of work (6.18):
  // a fifth of what the same two spheres of one material need.
  Particles p;
  const double r = 20.0;
  p.add({{0, 0, 0}, r, 1.0, {}, 0, 0});
  p.add({{2 * r, 0, 0}, r, 1.0, {}, 1, 0});
  p.add({{4 * r, 0, 0}, r, 1.0, {}, 1, 0});
  const double across = fracture_work(law.pair(p, 0, 1));
  EXPECT_NEAR(across, 2.0 * 0.3 * normal_cross_section(r, a.poisson), 1e-9 * across);
  EXPECT_NEAR(fracture_work(law.pair(p, 1, 2)), 5.0 * across, 1e-9 * across);
  EXPECT_DOUBLE_EQ(law.pair(p, 0, 1).delta_f, 4.0 * 0.3 / 0.2);  // (6.57)

  auto impossible = interface;
  impossible.poisson = 0.3;
  EXPECT_THROW(law.set_interface(0, 1, impossible), InputError);
  EXPECT_THROW(law.set_interface(0, 2, interface), InputError);
}
