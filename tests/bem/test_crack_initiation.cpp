// The crack initiation criterion (4.25) at micro-contact edges (§4.2): a
// sheared junction is in tension behind and in compression ahead, and (4.25)
// holds exactly when both reach the tensile strength.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "input_error_of.hpp"
#include "wearscale/bem/contact_clusters.hpp"
#include "wearscale/bem/crack_initiation.hpp"

using namespace wearscale;
using namespace wearscale::bem;

namespace {
const Grid2D kGrid = Grid2D::square(256, 1.0);

// One circular junction of radius 12 cells at (cx, cy) carrying q along x (Fig. 4.1).
struct ShearedJunction {
  VectorField traction{kGrid};
  RealField contact{kGrid};
  ShearedJunction(std::size_t cx, std::size_t cy, double q) {
    for (std::size_t i = 0; i < kGrid.nx; ++i)
      for (std::size_t j = 0; j < kGrid.ny; ++j) {
        const double di = static_cast<double>(i) - static_cast<double>(cx);
        const double dj = static_cast<double>(j) - static_cast<double>(cy);
        if (di * di + dj * dj <= 144.0) {
          traction.x(i, j) = q;
          contact(i, j) = 1.0;
        }
      }
  }
  PrincipalStresses surface_stress(double nu) const {
    SubsurfaceStress solid(kGrid, nu);
    solid.set_traction(traction);
    StressField s(kGrid);
    solid.stress(0.0, s);
    PrincipalStresses p(kGrid);
    principal_stresses(s, p);
    return p;
  }
};
}  // namespace

TEST(CrackInitiation, AShearedJunctionIsInTensionBehindAndCompressionAhead) {
  // A pure tangential load is antisymmetric in x: the trailing-edge tension and
  // the leading-edge compression are equal in magnitude (to rounding).
  const ShearedJunction j(128, 128, 1.0);
  const auto stress = j.surface_stress(0.3);
  const auto map = find_clusters(j.contact);
  ASSERT_EQ(map.clusters.size(), 1u);
  const auto check = crack_initiation(map, stress, 1.0, 0.0, 0.1)[0];
  EXPECT_GT(check.trailing_tension, 0.5);  // of the order of q (a stress concentration at the border)
  EXPECT_NEAR(check.leading_compression, -check.trailing_tension, 1e-9);
  // Sliding the other way swaps the edges.
  const auto reverse = crack_initiation(map, stress, -1.0, 0.0, 0.1)[0];
  EXPECT_LT(reverse.trailing_tension, check.trailing_tension);
}

TEST(CrackInitiation, Criterion425HoldsExactlyWhenBothEdgesReachTheStrength) {
  const ShearedJunction j(40, 200, 1.0);  // near the cell's border: periodic neighbours
  const auto stress = j.surface_stress(0.2);
  const auto map = find_clusters(j.contact);
  const double reached = crack_initiation(map, stress, 1.0, 0.0, 1.0)[0].trailing_tension;
  EXPECT_TRUE(crack_initiation(map, stress, 1.0, 0.0, 0.99 * reached)[0].initiates());   // (4.25a) and (4.25b)
  const auto above = crack_initiation(map, stress, 1.0, 0.0, 1.01 * reached)[0];
  EXPECT_FALSE(above.trailing);
  EXPECT_FALSE(above.initiates());
}

TEST(CrackInitiation, RefusesANonPositiveStrengthOrNoDirection) {
  const ShearedJunction j(128, 128, 1.0);
  const auto stress = j.surface_stress(0.3);
  const auto map = find_clusters(j.contact);
  EXPECT_THAT(input_error_of([&] { crack_initiation(map, stress, 1.0, 0.0, 0.0); }), ::testing::HasSubstr("σ_m > 0"));
  EXPECT_THAT(input_error_of([&] { crack_initiation(map, stress, 0.0, 0.0, 1.0); }), ::testing::HasSubstr("direction"));
}
