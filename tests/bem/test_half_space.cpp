// The periodic elastic half-space (§2.3.1): the Boussinesq–Cerruti tensor,
// reciprocity, closed-form displacements and elastic energies of ch. 4.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "wearscale/bem/half_space.hpp"
#include "wearscale/core/errors.hpp"

using namespace wearscale;
using namespace wearscale::bem;
using std::numbers::pi;

namespace {

// Two random traction fields (normal deviates from `seed`) and the body's
// displacements under them.
struct TwoLoads {
  VectorField p1, p2, u1, u2;
};
TwoLoads random_loads(HalfSpace& body, const Grid2D& grid, unsigned seed) {
  TwoLoads l{VectorField(grid), VectorField(grid), VectorField(grid), VectorField(grid)};
  std::mt19937 rng(seed);
  std::normal_distribution<double> n;
  for (auto* f : {&l.p1.x, &l.p1.y, &l.p1.z, &l.p2.x, &l.p2.y, &l.p2.z})
    for (auto& v : *f) v = n(rng);
  body.displacement(l.p1, l.u1);
  body.displacement(l.p2, l.u2);
  return l;
}

// The work of the traction p through the displacement u, summed over the cells.
double work(const VectorField& p, const VectorField& u) {
  double w = 0.0;
  for (std::size_t k = 0; k < p.grid().size(); ++k) w += p.x[k] * u.x[k] + p.y[k] * u.y[k] + p.z[k] * u.z[k];
  return w;
}
// Uniform traction `value` on a disc of diameter d centred at (cx, cy).
void disc(RealField& f, double d, double cx, double cy, double value) {
  const auto& g = f.grid();
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) {
      const double x = g.x(i) - cx, y = g.y(j) - cy;
      if (x * x + y * y <= 0.25 * d * d) f(i, j) += value;
    }
}

double pixel_area(const RealField& f) {
  double a = 0.0;
  for (double v : f) a += v != 0.0 ? 1.0 : 0.0;
  return a * f.grid().cell_area();
}

// Square-lattice sum Σ'1/|n| with a neutralising background (Bonsall &
// Maradudin 1977): the energy of periodic images of a loaded patch.
constexpr double kSquareLatticeMadelung = -3.9002649;

// Energy per cell of the periodic images of a patch carrying total tangential
// force Q, in the point-force limit: ½ Σ' Q²(1 − ν sin²θ)/(2πG|n|L), whose
// angular factor averages to (1 − ν/2) over each lattice shell.
double image_energy(double force, double g, double nu, double l) {
  return force * force * (1.0 - 0.5 * nu) * kSquareLatticeMadelung / (4.0 * pi * g * l);
}
}  // namespace

TEST(HalfSpace, GreenTensorIsHermitianAndMatchesBoussinesq) {
  const double g = 30e9, nu = 0.27, qx = 3.0, qy = -4.0;  // |q| = 5
  const auto f = HalfSpace::green_tensor(qx, qy, g, nu);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) EXPECT_EQ(f[a][b], std::conj(f[b][a])) << a << b;
  const double e_prime = 2.0 * g * (1.0 + nu) / (1.0 - nu * nu);
  EXPECT_NEAR(f[2][2].real(), 2.0 / (e_prime * 5.0), 1e-25);            // (2.35c): 2/(E' q)
  EXPECT_NEAR(f[0][0].real(), (1.0 - nu * 9.0 / 25.0) / (g * 5.0), 1e-25);  // (4.3)
  EXPECT_EQ(HalfSpace::green_tensor(0.0, 0.0, g, nu)[2][2], 0.0);       // zero mode
}

TEST(HalfSpace, IncompressibleBodiesDecoupleNormalAndTangential) {
  const auto f = HalfSpace::green_tensor(1.0, 2.0, 1.0, 0.5);
  EXPECT_EQ(std::abs(f[0][2]), 0.0);
  EXPECT_EQ(std::abs(f[2][1]), 0.0);
}

TEST(HalfSpace, BettiReciprocityHoldsForArbitraryTractions) {
  const Grid2D grid(32, 24, 1.0, 0.8);
  HalfSpace body(grid, 1.0, 0.3);
  const auto [p1, p2, u1, u2] = random_loads(body, grid, 7);
  const double w12 = work(p1, u2), w21 = work(p2, u1);
  EXPECT_NEAR(w12, w21, 1e-12 * std::abs(w12));
  EXPECT_GT(HalfSpace::elastic_energy(p1, u1), 0.0);  // the operator is positive
}

TEST(HalfSpace, ANormalLoadPullsSurfacePointsTowardsIt) {
  // Boussinesq (2.35a): u_x = −(1−2ν)P x/(4πG r²) outside the loaded disc.
  const Grid2D grid = Grid2D::square(256, 1.0);
  HalfSpace body(grid, 1.0, 0.2);
  VectorField p(grid), u(grid);
  disc(p.z, 0.05, 0.5, 0.5, 1.0);
  body.displacement(p, u);
  const std::size_t c = 128, off = 16;  // 0.0625 from the centre
  EXPECT_LT(u.x(c + off, c), 0.0);
  EXPECT_GT(u.x(c - off, c), 0.0);
  const double force = pixel_area(p.z);
  // x/r² is harmonic, so outside the disc its load acts as a point load; the
  // periodic images shift the value by about 1 % at this distance.
  const double expected = -(1.0 - 0.4) * force / (4.0 * pi * body.shear_modulus() * 0.0625);
  EXPECT_NEAR(u.x(c + off, c), expected, 0.02 * std::abs(expected));
}

TEST(HalfSpace, UniformPressureOnACircleMatchesJohnson) {
  // u_z(0) − u_z(a) = (2 p a / E')(1 − 2/π) for uniform p on radius a (Johnson §3.2).
  const Grid2D grid = Grid2D::square(1024, 1.0);
  HalfSpace body(grid, 2.0, 0.3);
  RealField p(grid), u(grid);
  const double a = 40.0 / 1024.0;
  disc(p, 2.0 * a, 0.5, 0.5, 1.0);
  body.normal_displacement(p, u);
  const double expected = 2.0 * a / body.contact_modulus() * (1.0 - 2.0 / pi);
  EXPECT_NEAR(u(512, 512) - u(512 + 40, 512), expected, 0.01 * expected);
}

TEST(HalfSpace, TheFullOperatorAgreesWithTheNormalOne) {
  const Grid2D grid(64, 48, 2.0, 1.5);
  HalfSpace body(grid, 3.0, 0.1);
  VectorField p(grid), u(grid);
  RealField uz(grid);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> d(0.0, 1.0);
  for (auto& v : p.z) v = d(rng);
  body.displacement(p, u);
  body.normal_displacement(p.z, uz);
  for (std::size_t k = 0; k < grid.size(); ++k) ASSERT_NEAR(u.z[k], uz[k], 1e-12);
}

TEST(HalfSpace, ShearedCircleStoresTheEnergyOf433) {
  // E_el,1 = (2−ν) d³ q² / (12 G)  (4.33), plus the energy of the periodic images.
  const std::size_t n = 2048;
  const Grid2D grid = Grid2D::square(n, 1.0);
  const double nu = 0.3, d = 64.0 / n, q = 1.0;
  HalfSpace body(grid, 1.0, nu);
  VectorField p(grid), u(grid);
  disc(p.x, d, 0.5, 0.5, q);
  body.displacement(p, u);
  const double g = body.shear_modulus();
  const double d_eff = std::sqrt(4.0 * pixel_area(p.x) / pi);  // the pixelated disc's diameter
  const double expected = (2.0 - nu) * std::pow(d_eff, 3) * q * q / (12.0 * g) +
                          image_energy(q * pixel_area(p.x), g, nu, 1.0);
  EXPECT_NEAR(HalfSpace::elastic_energy(p, u), expected, 0.01 * expected);
}

TEST(HalfSpace, TwoShearedCirclesFollow444) {
  // E_el,2 ≈ (2−ν)d³q²/(6G) + πd⁴q²(1 − ν sin²θ)/(32 G l)   (4.44), within a few % for l ≥ d.
  const std::size_t n = 2048;
  const Grid2D grid = Grid2D::square(n, 1.0);
  const double nu = 0.3, d = 48.0 / n, q = 1.0;
  HalfSpace body(grid, 1.0, nu);
  const double g = body.shear_modulus();
  for (double theta : {0.0, pi / 2}) {
    double previous = std::numeric_limits<double>::infinity();
    for (double l_over_d : {1.0, 1.5, 2.0, 4.0}) {
      const double l = l_over_d * d;
      VectorField p(grid), u(grid);
      disc(p.x, d, 0.5 - 0.5 * l * std::cos(theta), 0.5 - 0.5 * l * std::sin(theta), q);
      disc(p.x, d, 0.5 + 0.5 * l * std::cos(theta), 0.5 + 0.5 * l * std::sin(theta), q);
      body.displacement(p, u);
      const double area = 0.5 * pixel_area(p.x), d_eff = std::sqrt(4.0 * area / pi);
      const double e1 = (2.0 - nu) * std::pow(d_eff, 3) * q * q / (12.0 * g);
      const double inter = pi * std::pow(d_eff, 4) * q * q * (1.0 - nu * std::pow(std::sin(theta), 2)) / (32.0 * g * l);
      const double expected = 2.0 * e1 + inter + image_energy(2.0 * q * area, g, nu, 1.0);
      const double got = HalfSpace::elastic_energy(p, u);
      // (4.44) is a far-field expansion: measured +3.2 % at l = d (θ = π/2), +1.1 % (θ = 0),
      // under 1 % from l = 1.5d and vanishing with distance, as Fig. 4.4 shows.
      const double tolerance = l_over_d < 1.5 ? 0.04 : 0.01;
      EXPECT_NEAR(got, expected, tolerance * expected) << "θ = " << theta << ", l/d = " << l_over_d;
      EXPECT_GT(got, 2.0 * e1);  // bounded by 2E_el,1 and 4E_el,1
      EXPECT_LT(got, 4.0 * e1);
      EXPECT_LT(got, previous);  // interaction decays with distance
      previous = got;
    }
  }
}

TEST(HalfSpace, RefusesUnphysicalMaterials) {
  const Grid2D grid = Grid2D::square(8, 1.0);
  EXPECT_THROW(HalfSpace(grid, -1.0, 0.3), InputError);
  EXPECT_THROW(HalfSpace(grid, 1.0, 0.6), InputError);
  EXPECT_THROW(HalfSpace(grid, 1.0, -1.0), InputError);
  try {
    HalfSpace(grid, 1.0, 0.7);
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("0.7"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("ν ≤ 0.5"));
  }
}

// --- Free boundary: a window on an unbounded half-space (zero padding, Love's cells) ---

TEST(HalfSpace, FreeCellUnderUniformPressureSinksAsLovesRectangle) {
  // The centre of a square cell of side h under p sinks by (1−ν²) p h · 4 ln(1+√2) / (πE)
  // (Love 1929); far away the cell acts as Boussinesq's point load P = p h²,
  // u = (1−ν²) P / (πE r), the difference being h²/(24 r²) of it.
  const double e = 3.0, nu = 0.3, l = 2.0;
  const std::size_t n = 64;
  const Grid2D grid = Grid2D::square(n, l);
  HalfSpace body(grid, e, nu, Boundary::Free, Response::Normal);
  RealField p(grid), u(grid);
  const std::size_t c = n / 2;
  p(c, c) = 1.0;
  body.normal_displacement(p, u);
  const double h = grid.dx(), es = e / (1.0 - nu * nu);
  EXPECT_NEAR(u(c, c), 4.0 * h * std::log(1.0 + std::sqrt(2.0)) / (pi * es), 1e-12 * u(c, c));
  EXPECT_NEAR(body.self_compliance(), u(c, c), 1e-12 * u(c, c));
  for (std::size_t d : {10ul, 20ul, 31ul}) {
    const double r = static_cast<double>(d) * h, point = h * h / (pi * es * r);
    EXPECT_NEAR(u(c + d, c), point, 0.05 * (h * h) / (r * r) * point) << d << " cells away";
    EXPECT_NEAR(u(c, c - d), point, 0.05 * (h * h) / (r * r) * point) << d << " cells away";
  }
  double mean = 0.0;
  for (double v : u) mean += v;
  EXPECT_GT(mean, 0.0);  // the true displacement: no zero mode removed
}

TEST(HalfSpace, FreeCellLoadsFollowBoussinesqAndCerrutiFarAway) {
  // Point solutions (Johnson 1985, §2.2, (3.19)) for P on one cell, 12 × 5 cells away.
  const double e = 2.0, nu = 0.25, l = 1.0;
  const std::size_t n = 48, c = 16;
  const Grid2D grid = Grid2D::square(n, l);
  HalfSpace body(grid, e, nu, Boundary::Free);
  const double h = grid.dx(), g = body.shear_modulus(), force = h * h;
  const long dx = 12, dy = 5;
  const double x = dx * h, y = dy * h, r = std::hypot(x, y);
  // The cell differs from the point by the next term of its expansion, (h²/24) ∇² of
  // the point solution: about (h/r)²/24 relative (more for xy, which varies faster).
  const double tol = 0.05 * (h * h) / (r * r);
  auto load = [&](int component) {
    VectorField p(grid), u(grid);
    (component == 0 ? p.x : component == 1 ? p.y : p.z)(c, c) = 1.0;
    body.displacement(p, u);
    return std::array<double, 3>{u.x(c + dx, c + dy), u.y(c + dx, c + dy), u.z(c + dx, c + dy)};
  };
  const auto from_x = load(0), from_z = load(2);
  const double xx = force / (2.0 * pi * g) * ((1.0 - nu) / r + nu * x * x / (r * r * r));
  const double xy = force / (2.0 * pi * g) * nu * x * y / (r * r * r);
  const double zz = force * (1.0 - nu) / (2.0 * pi * g * r);
  const double xz = -force * (1.0 - 2.0 * nu) / (4.0 * pi * g) * x / (r * r);  // u_x from p_z, towards the load
  EXPECT_NEAR(from_x[0], xx, tol * std::abs(xx));
  EXPECT_NEAR(from_x[1], xy, 4.0 * tol * std::abs(xy));
  EXPECT_NEAR(from_x[2], -xz, tol * std::abs(xz));  // Betti: u_z from p_x = −(u_x from p_z)
  EXPECT_NEAR(from_z[0], xz, tol * std::abs(xz));
  EXPECT_NEAR(from_z[2], zz, tol * std::abs(zz));
}

TEST(HalfSpace, FreeOperatorIsSymmetricAndPositiveAndMatchesItsNormalBlock) {
  const Grid2D grid(24, 20, 1.2, 1.0);
  HalfSpace body(grid, 1.0, 0.3, Boundary::Free);
  HalfSpace normal = HalfSpace::normal(grid, body.contact_modulus(), Boundary::Free);
  RealField uz(grid);
  const auto [p1, p2, u1, u2] = random_loads(body, grid, 11);
  const double w12 = work(p1, u2), w21 = work(p2, u1);
  EXPECT_NEAR(w12, w21, 1e-12 * std::abs(w12));
  EXPECT_GT(HalfSpace::elastic_energy(p1, u1), 0.0);
  // Parseval's forms on the padded grid equal the sums over the window.
  auto w = body.workspace();
  const auto form = body.form(p1, w);
  double nn = 0.0;
  for (std::size_t k = 0; k < grid.size(); ++k) nn += p1.z[k] * u1.z[k];
  VectorField only_z(grid), u_only_z(grid);
  only_z.z = p1.z;
  body.displacement(only_z, u_only_z);
  double nn_direct = 0.0;
  for (std::size_t k = 0; k < grid.size(); ++k) nn_direct += p1.z[k] * u_only_z.z[k];
  EXPECT_NEAR(form.nn, nn_direct, 1e-10 * std::abs(nn_direct));
  EXPECT_NEAR(form.nn + form.tt + 2.0 * form.nt, 2.0 * HalfSpace::elastic_energy(p1, u1) / grid.cell_area(),
              1e-10 * std::abs(nn));
  normal.normal_displacement(p1.z, uz);
  for (std::size_t k = 0; k < grid.size(); ++k) ASSERT_NEAR(uz[k], u_only_z.z[k], 1e-12 * std::abs(u_only_z.z[k]) + 1e-14);
}
