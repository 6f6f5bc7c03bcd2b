// The elastic constants of an MD sample by finite strains: the moduli of a
// stiffness matrix against closed forms, the deck, and the parser of its rows.
#include <gtest/gtest.h>

#include "md_test_support.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/md/elastic_constants.hpp"

using namespace wearscale;
using namespace wearscale::md;
using md_test::has_line;

TEST(ElasticModuli, CubicCrystalAlong001FollowsTheClosedForms) {
  // Mishin et al. 2001 Cu: C11 = 169.9, C12 = 122.6, C44 = 76.2 GPa.
  const double c11 = 169.9e9, c12 = 122.6e9, c44 = 76.2e9;
  const ElasticModuli m = elastic_moduli(cubic_stiffness(c11, c12, c44));
  // E<100> = (C11 − C12)(C11 + 2 C12)/(C11 + C12), ν<100> = C12/(C11 + C12).
  EXPECT_NEAR(m.young_z, (c11 - c12) * (c11 + 2 * c12) / (c11 + c12), 1e-9 * c11);
  EXPECT_NEAR(m.poisson_zx, c12 / (c11 + c12), 1e-12);
  EXPECT_NEAR(m.shear_xz, c44, 1e-9 * c44);
  // Voigt–Reuss–Hill: K = (C11 + 2 C12)/3 in both bounds; G_V = (C11 − C12 + 3 C44)/5,
  // G_R = 5 (C11 − C12) C44 / (4 C44 + 3 (C11 − C12)).
  EXPECT_NEAR(m.bulk, (c11 + 2 * c12) / 3, 1e-9 * c11);
  const double gv = (c11 - c12 + 3 * c44) / 5, gr = 5 * (c11 - c12) * c44 / (4 * c44 + 3 * (c11 - c12));
  EXPECT_NEAR(m.shear, 0.5 * (gv + gr), 1e-9 * c44);
  EXPECT_TRUE(m.stable());
  EXPECT_NEAR(m.min_eigenvalue, std::min({c11 - c12, c44, c11 + 2 * c12}), 1e-6 * c11);
}

TEST(ElasticModuli, AnIsotropicSolidGivesBackItsEAndNu) {
  const double e = 73e9, nu = 0.17, g = e / (2 * (1 + nu)), lambda = e * nu / ((1 + nu) * (1 - 2 * nu));
  const ElasticModuli m = elastic_moduli(cubic_stiffness(lambda + 2 * g, lambda, g));
  EXPECT_NEAR(m.young, e, 1e-9 * e);
  EXPECT_NEAR(m.poisson, nu, 1e-12);
  EXPECT_NEAR(m.young_z, e, 1e-9 * e);
  EXPECT_NEAR(m.poisson_zx, nu, 1e-12);
}

TEST(ElasticModuli, BornInstabilityIsSeen) {
  // C11 < C12: the tetragonal shear C' = (C11 − C12)/2 is negative (bcc Cu, say).
  EXPECT_FALSE(elastic_moduli(cubic_stiffness(100e9, 120e9, 50e9)).stable());
  EXPECT_FALSE(elastic_moduli(cubic_stiffness(150e9, 70e9, -1e9)).stable());
  EXPECT_THROW(elastic_moduli(Stiffness{}), NumericalError);
}

TEST(ElasticDeck, StrainsEachVoigtComponentBothWaysFromOneMinimisedState) {
  materials::InteratomicModel m;
  m.pair_style = "eam/alloy";
  m.potential = "Cu_mishin1.eam.alloy";
  m.elements = {"Cu"};
  m.masses = {63.546};
  m.structure = materials::Structure::Fcc;
  m.lattice_constant = 3.615e-10;
  ElasticDeckFiles f;
  f.potential = "Cu_mishin1.eam.alloy";
  const std::string d = elastic_deck(m, {4, 4, {}, true}, f, 1e-3, "test");
  EXPECT_TRUE(has_line(d, "lattice fcc 3.615 orient x 1 0 0 orient y 0 1 0 orient z 0 0 1"));
  EXPECT_TRUE(has_line(d, "region box block 0 4 0 4 0 4"));
  EXPECT_TRUE(has_line(d, "pair_coeff * * Cu_mishin1.eam.alloy Cu"));
  EXPECT_TRUE(has_line(d, "mass 1 63.546"));
  EXPECT_TRUE(has_line(d, "fix relax all box/relax aniso 0.0 vmax 0.001")) << "the ideal lattice at zero stress";
  EXPECT_TRUE(has_line(d, "write_restart unstrained.restart"));
  EXPECT_TRUE(has_line(d, "change_box all x scale 1.001 remap units box"));
  EXPECT_TRUE(has_line(d, "change_box all x scale 0.999 remap units box"));
  EXPECT_TRUE(has_line(d, "change_box all yz final $(0.001*lz) remap units box"));
  EXPECT_TRUE(has_line(d, "change_box all xz final $(-0.001*lz) remap units box"));
  EXPECT_TRUE(has_line(d, "change_box all xy final $(0.001*ly) remap units box"));
  std::size_t restores = 0;
  for (auto p = d.find("read_restart"); p != std::string::npos; p = d.find("read_restart", p + 1)) ++restores;
  EXPECT_EQ(restores, 12u) << "six strains, two signs, each from the unstrained state";
  // The sample as built: its cells, no box relaxation.
  const std::string s = elastic_deck(m, {6, 6, {}, false}, f, 1e-3, "test");
  EXPECT_FALSE(has_line(s, "fix relax all box/relax"));
  EXPECT_TRUE(has_line(s, "region box block 0 6 0 6 0 6"));
  // An amorphous sample: the quenched data, relaxed.
  const std::string a = elastic_deck(m, {1, 1, "quenched.data", true}, f, 1e-3, "test");
  EXPECT_TRUE(has_line(a, "read_data quenched.data"));
  EXPECT_FALSE(has_line(a, "lattice fcc"));
  EXPECT_THROW(elastic_deck(m, {4, 4, {}, true}, f, 0.1, "test"), InputError);
}

TEST(ElasticParser, CentralDifferencesGiveBackTheStiffness) {
  const ElasticResult r = parse_elastic(md_test::elastic_rows(151.4, 76.4, 56.4), 1e-3, "elastic.txt");
  EXPECT_NEAR(r.c[0][0], 151.4e9, 1e3);
  EXPECT_NEAR(r.c[1][0], 76.4e9, 1e3);
  EXPECT_NEAR(r.c[4][4], 56.4e9, 1e3);
  EXPECT_NEAR(r.c[3][0], 0.0, 1e3);
  EXPECT_NEAR(r.lx, 16.293e-10, 1e-20);
  // A missing row, a non-number, an infinity: the run is unusable.
  std::string rows = md_test::elastic_rows(151.4, 76.4, 56.4);
  EXPECT_THROW(parse_elastic(rows.substr(0, rows.rfind("12 6")), 1e-3, "x"), NumericalError);
  EXPECT_THROW(parse_elastic(rows + "3 2 1 a b c d e f 1 1 1\n", 1e-3, "x"), NumericalError);
  EXPECT_THROW(parse_elastic(rows + "3 2 1 inf 0 0 0 0 0 1 1 1\n", 1e-3, "x"), NumericalError);
}
