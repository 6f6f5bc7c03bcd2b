// Carving a sample with shapes (§6.3: surfaces and a cylindrical junction cut
// from a relaxed box), tagging bodies and picking wall layers. Membership is
// decided by a particle's centre; each test checks it against the geometry
// written out independently.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "wearscale/dem/shapes.hpp"

using namespace wearscale::dem;

namespace {
// A 10 × 10 × 10 grid of unit spheres at integer + 0.5 coordinates.
Particles grid() {
  Particles p;
  for (int k = 0; k < 10; ++k)
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 10; ++i) p.add({{i + 0.5, j + 0.5, k + 0.5}, 0.5, 1.0, {}, 0, 0});
  return p;
}

std::size_t count_if(const Particles& p, auto inside) {
  std::size_t n = 0;
  for (const auto& x : p.position) n += inside(x) ? 1 : 0;
  return n;
}
}  // namespace

TEST(Shapes, HalfSpaceKeepsThePointsBehindItsOutwardNormal) {
  auto p = grid();
  const std::size_t removed = carve(p, below(2, 4.0), Carve::keep_inside);
  EXPECT_EQ(removed, 600u);  // layers z = 4.5 … 9.5
  EXPECT_EQ(p.size(), 400u);
  for (const auto& x : p.position) EXPECT_LE(x.z, 4.0);
  // A tilted plane through (5, 5, 5) with outward normal (1, 1, 0).
  auto q = grid();
  const HalfSpace tilted{{5, 5, 5}, {1, 1, 0}};
  const auto expected = count_if(q, [](const Vec3& x) { return x.x + x.y <= 10.0; });
  carve(q, tilted, Carve::keep_inside);
  EXPECT_EQ(q.size(), expected);
  EXPECT_EQ(expected, 550u);  // i + j ≤ 9: 55 columns of 10
}

TEST(Shapes, CylinderKeepsExactlyTheParticlesInside) {
  // The junction of §6.3: a vertical cylinder of diameter D = 6 and height 4.
  auto p = grid();
  const Cylinder junction{{5, 5, 3}, {5, 5, 7}, 3.0};
  auto inside = [](const Vec3& x) {
    const double r2 = (x.x - 5) * (x.x - 5) + (x.y - 5) * (x.y - 5);
    return r2 <= 9.0 && x.z >= 3.0 && x.z <= 7.0;
  };
  const auto expected = count_if(p, inside);
  EXPECT_EQ(expected, 32u * 4u);  // 32 columns within r = 3, 4 layers
  carve(p, junction, Carve::keep_inside);
  ASSERT_EQ(p.size(), expected);
  for (const auto& x : p.position) EXPECT_TRUE(inside(x));
  // Any axis direction: the same cylinder along x.
  auto q = grid();
  carve(q, Cylinder{{3, 5, 5}, {7, 5, 5}, 3.0}, Carve::keep_inside);
  EXPECT_EQ(q.size(), expected);
}

TEST(Shapes, BallAndBlockKeepExactlyTheParticlesInside) {
  auto p = grid();
  const Ball ball{{5, 5, 5}, 3.2};
  const auto in_ball = count_if(p, [](const Vec3& x) {
    return (x.x - 5) * (x.x - 5) + (x.y - 5) * (x.y - 5) + (x.z - 5) * (x.z - 5) <= 3.2 * 3.2;
  });
  EXPECT_EQ(carve(p, ball, Carve::keep_inside), 1000u - in_ball);
  for (const auto& x : p.position) EXPECT_LE(norm(x - Vec3{5, 5, 5}), 3.2);
  auto q = grid();
  carve(q, Block{{2, 3, 4}, {5, 9, 6}}, Carve::keep_inside);
  EXPECT_EQ(q.size(), 3u * 6u * 2u);
}

TEST(Shapes, RemoveInsideKeepsTheComplementInOrder) {
  auto p = grid();
  const Ball ball{{5, 5, 5}, 3.2};
  const auto inside = indices_inside(p, ball);
  const auto removed = carve(p, ball, Carve::remove_inside);
  EXPECT_EQ(removed, inside.size());
  EXPECT_EQ(p.size(), 1000u - inside.size());
  for (std::size_t i = 1; i < p.size(); ++i) EXPECT_LT(p.id[i - 1], p.id[i]);  // order kept
  for (const auto& x : p.position) EXPECT_GT(norm(x - Vec3{5, 5, 5}), 3.2);
}

TEST(Shapes, SetBodyTagsOnlyTheParticlesInside) {
  // Two surfaces and a junction: bodies 1 (below z = 3), 2 (above z = 7).
  auto p = grid();
  EXPECT_EQ(set_body(p, below(2, 3.0), 1), 300u);
  EXPECT_EQ(set_body(p, above(2, 7.0), 2), 300u);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double z = p.position[i].z;
    EXPECT_EQ(p.body[i], z < 3.0 ? 1 : (z > 7.0 ? 2 : 0));
  }
}

TEST(Shapes, WallLayerOfThicknessOneAndAHalfD0) {
  // The top wall of §6.3: centres within 1.5 d0 (d0 = 1) of the highest.
  const auto p = grid();
  const auto [lo, hi] = extent(p, 2);
  EXPECT_EQ(lo, 0.5);
  EXPECT_EQ(hi, 9.5);
  const auto top = indices_inside(p, above(2, hi - 1.5));
  EXPECT_EQ(top.size(), 200u);  // z = 8.5 and 9.5
  for (std::size_t i : top) EXPECT_GE(p.position[i].z, 8.0);
}

TEST(Shapes, VolumesOfTheFiniteShapes) {
  EXPECT_NEAR(volume(Cylinder{{0, 0, 0}, {0, 3, 4}, 2.0}), std::numbers::pi * 4.0 * 5.0, 1e-12);
  EXPECT_NEAR(volume(Ball{{1, 1, 1}, 2.0}), 4.0 / 3.0 * std::numbers::pi * 8.0, 1e-12);
  EXPECT_EQ(volume(Block{{0, 0, 0}, {1, 2, 3}}), 6.0);
  EXPECT_TRUE(std::isinf(volume(below(0, 1.0))));
}
