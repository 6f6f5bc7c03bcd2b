// Frictionless normal contact (Polonsky–Keer, §2.3.2): exact periodic
// solutions (Westergaard), Hertz within the limits of (A.2), and the
// Hertz–Signorini–Moreau conditions (2.43) at the solution.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "wearscale/bem/hertz.hpp"
#include "wearscale/bem/normal_contact.hpp"
#include "wearscale/core/errors.hpp"

using namespace wearscale;
using namespace wearscale::bem;
using std::numbers::pi;

namespace {
// A rigid paraboloid of radius R with its summit at the centre of the cell.
RealField paraboloid(const Grid2D& g, double radius) {
  RealField h(g);
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) {
      const double x = g.x(i) - 0.5 * g.lx, y = g.y(j) - 0.5 * g.ly;
      h(i, j) = -(x * x + y * y) / (2.0 * radius);
    }
  return h;
}

// Wavy surface h = Δ cos(2πx/λ), λ = Lx (Westergaard).
RealField wavy(const Grid2D& g, double amplitude) {
  RealField h(g);
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) h(i, j) = amplitude * std::cos(2.0 * pi * g.x(i) / g.lx);
  return h;
}

// Hertz surface displacement outside the contact (Johnson 1985, (3.42b)), with 1/E*.
double hertz_outside(const HertzContact& c, double r) {
  const double a = c.contact_radius(), p0 = c.peak_pressure();
  return p0 / (2.0 * a * c.e_star) * ((2.0 * a * a - r * r) * std::asin(a / r) + r * a * std::sqrt(1.0 - a * a / (r * r)));
}

// u(0) − u(r) added by the periodic images of a load F (point-load limit).
double image_displacement_difference(double force, double e_star, double l, double r) {
  double sum = 0.0;
  const int m = 300;
  for (int i = -m; i <= m; ++i)
    for (int j = -m; j <= m; ++j) {
      if (i == 0 && j == 0) continue;
      const double x = i * l, y = j * l;
      sum += 1.0 / std::hypot(x, y) - 1.0 / std::hypot(x - r, y);
    }
  return force / (pi * e_star) * sum;
}

struct HertzCase {
  const char* name;
  double radius, load, e_star, size;
  std::size_t n;
};

void PrintTo(const HertzCase& c, std::ostream* os) { *os << c.name; }
}  // namespace

TEST(NormalContact, WavySurfaceInFullContactHasWestergaardsPressure) {
  // p* = π E* Δ/λ; for p0 ≥ p*, p = p0 + p* cos(2πx/λ) exactly.
  const Grid2D g(256, 4, 1.0, 1.0 / 64.0);
  const double e_star = 2.0, delta = 0.01, p_star = pi * e_star * delta;
  NormalContact contact(wavy(g, delta), e_star);
  const auto r = contact.solve_mean_pressure(1.5 * p_star);
  EXPECT_EQ(r.contact_fraction, 1.0);
  for (std::size_t i = 0; i < g.nx; ++i)
    ASSERT_NEAR(contact.pressure()(i, 0), 1.5 * p_star + p_star * std::cos(2.0 * pi * g.x(i)), 1e-9 * p_star);
}

TEST(NormalContact, WavySurfaceInPartialContactFollowsWestergaard) {
  // p0 = p* sin²(πa/λ): at p0 = p*/2 the contact covers half the period.
  const std::size_t n = 1024;
  const Grid2D g(n, 4, 1.0, 4.0 / n);
  const double e_star = 1.0, delta = 0.01, p_star = pi * e_star * delta;
  NormalContact contact(wavy(g, delta), e_star);
  const auto r = contact.solve_mean_pressure(0.5 * p_star);
  EXPECT_NEAR(r.contact_fraction, 0.5, 2.0 / n);  // a resolved to a grid point on each side
  const double s2 = 0.5;                           // sin²(πa/λ)
  for (std::size_t i : {0ul, 64ul, 128ul, 192ul}) {  // inside |x| < a = λ/4
    const double x = g.x(i), sx = std::sin(pi * x);
    const double expected = 2.0 * 0.5 * p_star * std::cos(pi * x) / s2 * std::sqrt(s2 - sx * sx);
    EXPECT_NEAR(contact.pressure()(i, 0), expected, 0.01 * p_star) << "x = " << x;
  }
}

class HertzContactTest : public ::testing::TestWithParam<HertzCase> {};

TEST_P(HertzContactTest, ContactRadiusPeakPressureAndApproachWithin2Percent) {
  const auto& c = GetParam();
  const Grid2D g = Grid2D::square(c.n, c.size);
  const HertzContact hertz{c.radius, c.load, c.e_star};
  const double a = hertz.contact_radius();
  ASSERT_LT(2.0 * a, c.size / 10.0) << "(A.2): the contact must be small against the cell";
  ASSERT_LT(g.dx(), 2.0 * a / 10.0) << "(A.2): and well resolved";

  NormalContact contact(paraboloid(g, c.radius), c.e_star);
  const auto r = contact.solve_mean_pressure(c.load / g.area());
  const double a_num = std::sqrt(r.contact_fraction * g.area() / pi);
  EXPECT_NEAR(a_num, a, 0.02 * a);
  const std::size_t mid = c.n / 2;
  EXPECT_NEAR(contact.pressure()(mid, mid), hertz.peak_pressure(), 0.02 * hertz.peak_pressure());

  // Approach of the summit relative to a surface point at r = 2a, with the
  // periodic images' share added to the closed form.
  const std::size_t off = static_cast<std::size_t>(std::lround(2.0 * a / g.dx()));
  const double r_ref = static_cast<double>(off) * g.dx();
  const double expected = hertz.approach() - hertz_outside(hertz, r_ref) +
                          image_displacement_difference(c.load, c.e_star, c.size, r_ref);
  const double got = contact.displacement()(mid, mid) - contact.displacement()(mid + off, mid);
  EXPECT_NEAR(got, expected, 0.02 * expected);
  RecordProperty("a_relative_error", std::to_string(a_num / a - 1.0));
  RecordProperty("p0_relative_error", std::to_string(contact.pressure()(mid, mid) / hertz.peak_pressure() - 1.0));
  RecordProperty("approach_relative_error", std::to_string(got / expected - 1.0));
  RecordProperty("iterations", std::to_string(r.iterations));
  EXPECT_NEAR(r.mean_pressure * g.area(), c.load, 1e-10 * c.load);
}

INSTANTIATE_TEST_SUITE_P(
    Spheres, HertzContactTest,
    ::testing::Values(
        // The pin of the pin-on-disc test (§8.1): a = 39.1 µm, p0 = 312 MPa.
        HertzCase{"pin", 3e-3, 1.0, effective_modulus(73e9, 0.17, 73e9, 0.17), 1e-3, 512},
        HertzCase{"unit", 1.0, 4.0 * std::pow(0.04, 3) / 3.0, 1.0, 1.0, 512},
        HertzCase{"stiff", 0.05, 20.0, 150e9, 4e-3, 512}),
    [](const auto& p) { return std::string(p.param.name); });

TEST(NormalContact, SolutionSatisfiesTheSignoriniConditions) {
  const Grid2D g = Grid2D::square(128, 1.0);
  NormalContact contact(paraboloid(g, 2.0), 1.0);
  const auto r = contact.solve_mean_pressure(2e-3, {1e-12, 10000});
  EXPECT_LT(r.error, 1e-12);
  double min_gap = INFINITY, max_pg = 0.0;
  for (std::size_t k = 0; k < g.size(); ++k) {
    ASSERT_GE(contact.pressure()[k], 0.0);  // (2.43a)
    min_gap = std::min(min_gap, contact.gap()[k]);
    max_pg = std::max(max_pg, contact.pressure()[k] * std::abs(contact.gap()[k]));
  }
  const double u_scale = contact.displacement()(64, 64);
  EXPECT_GT(min_gap, -1e-10 * u_scale);  // (2.43b)
  EXPECT_EQ(max_pg, 0.0);                // (2.43c): the gap is closed wherever p > 0
}

TEST(NormalContact, ImposedInterferenceGivesTheMatchingLoad) {
  const Grid2D g = Grid2D::square(128, 1.0);
  NormalContact contact(paraboloid(g, 2.0), 1.0);
  const auto by_pressure = contact.solve_mean_pressure(1e-3);
  contact.reset();
  const auto by_interference = contact.solve_interference(by_pressure.interference);
  EXPECT_NEAR(by_interference.mean_pressure, 1e-3, 1e-8);
  EXPECT_NEAR(by_interference.interference, by_pressure.interference, 1e-9 * by_pressure.interference);
  EXPECT_EQ(contact.solve_interference(-1.0).mean_pressure, 0.0);  // apart: no load
}

TEST(NormalContact, AWarmStartConvergesFaster) {
  const Grid2D g = Grid2D::square(256, 1.0);
  NormalContact contact(paraboloid(g, 2.0), 1.0);
  const int cold = contact.solve_mean_pressure(1e-3).iterations;
  const int warm = contact.solve_mean_pressure(1.02e-3).iterations;
  EXPECT_LT(warm, cold);
}

TEST(NormalContact, ReportsTheElasticEnergyOfItsSolution) {
  // E_el = ½ ∫ p u dA (2.42) at the solution, positive for a compressive load.
  const Grid2D g = Grid2D::square(64, 1.0);
  NormalContact contact(paraboloid(g, 1.0), 1.0);
  const auto r = contact.solve_mean_pressure(1e-3);
  double sum = 0.0;
  for (std::size_t k = 0; k < g.size(); ++k) sum += contact.pressure()[k] * contact.displacement()[k];
  EXPECT_NEAR(r.elastic_energy, 0.5 * sum * g.cell_area(), 1e-14);
  EXPECT_GT(r.elastic_energy, 0.0);
}

TEST(NormalContact, BadInputIsRefused) {
  const Grid2D g = Grid2D::square(16, 1.0);
  EXPECT_THROW(NormalContact(paraboloid(g, 1.0), -1.0), InputError);
  NormalContact contact(paraboloid(g, 1.0), 1.0);
  EXPECT_THROW(contact.solve_mean_pressure(-1.0), InputError);
  RealField bad = paraboloid(g, 1.0);
  bad(3, 3) = std::nan("");
  EXPECT_THROW(contact.set_surface(bad), InputError);
}

TEST(NormalContact, NonConvergenceIsANumericalErrorNamingTheSolver) {
  const Grid2D g = Grid2D::square(64, 1.0);
  NormalContact contact(paraboloid(g, 1.0), 1.0);
  try {
    contact.solve_mean_pressure(1e-3, {1e-14, 2});
    FAIL() << "two iterations cannot reach 1e-14";
  } catch (const NumericalError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("Polonsky"));
    EXPECT_THAT(e.solver(), ::testing::HasSubstr("Polonsky"));
    EXPECT_EQ(e.step(), 2);
    EXPECT_EQ(e.quantity(), "orthogonality error");
    // The residual history: where it started and the errors of the last iterations.
    EXPECT_THAT(e.detail(), ::testing::HasSubstr("at the first iteration"));
    EXPECT_THAT(e.detail(), ::testing::HasSubstr("last 2 errors"));
  }
}

TEST(NormalContact, ARestoredWarmStartGivesTheSameSolveBitForBit) {
  // What a checkpoint keeps of the solver between solves: the last pressure
  // and mean gap. A fresh solver given them solves exactly as the original.
  const Grid2D g = Grid2D::square(32, 1.0);
  NormalContact a(paraboloid(g, 0.5), 1.0);
  a.solve_mean_pressure(1e-3, {1e-10, 1000});
  const std::vector<double> p(a.pressure().begin(), a.pressure().end());
  const double shift = a.warm_gap_shift();
  RealField next = paraboloid(g, 0.45);
  a.set_surface(next);
  const auto ra = a.solve_mean_pressure(1.2e-3, {1e-10, 1000});

  NormalContact b(next, 1.0);
  b.set_warm_start(p, shift);
  const auto rb = b.solve_mean_pressure(1.2e-3, {1e-10, 1000});
  EXPECT_EQ(ra.iterations, rb.iterations);
  EXPECT_EQ(ra.error, rb.error);
  for (std::size_t k = 0; k < g.size(); ++k) ASSERT_EQ(a.pressure()[k], b.pressure()[k]) << k;
  EXPECT_THROW(b.set_warm_start(std::vector<double>(3, 0.0), 0.0), InputError);
}

TEST(NormalContact, GrowsFromAOnePointContactWhenTheLoadRises) {
  // A tiny load rests on the summit point alone; the warm-started solve at a
  // larger load must bring the neighbours in (its first direction is zero).
  const Grid2D g = Grid2D::square(32, 1.0);
  NormalContact contact(paraboloid(g, 0.5), 1.0);
  const auto small = contact.solve_mean_pressure(1e-9);
  EXPECT_EQ(small.contact_fraction, 1.0 / g.size());
  const auto large = contact.solve_mean_pressure(1e-3);
  EXPECT_GT(large.contact_fraction, 5.0 / g.size());
  EXPECT_LT(large.error, 1e-12);
}

// --- Free boundary: an isolated sphere, no periodic images ---

class FreeHertzTest : public ::testing::TestWithParam<HertzCase> {};

TEST_P(FreeHertzTest, ApproachPeakPressureAndContactRadiusMatchHertzWithoutImageCorrections) {
  // c.n cells across the contact (64 and more), a window of c.size contact
  // diameters (padded to twice that). Free: nothing depends on the window but
  // its being larger than the contact, so the cases differ by their resolution.
  const auto& c = GetParam();
  const HertzContact hertz{c.radius, c.load, c.e_star};
  const double a = hertz.contact_radius(), dx = 2.0 * a / static_cast<double>(c.n);
  const auto cells = static_cast<std::size_t>(c.size * static_cast<double>(c.n));
  const Grid2D g = Grid2D::square(cells, static_cast<double>(cells) * dx);
  NormalContact contact(paraboloid(g, c.radius), c.e_star, Boundary::Free);
  const auto r = contact.solve_mean_pressure(c.load / g.area(), {1e-10, 1000});
  // Measured: δ within 3e-5, p0 within 5e-5, a (from the count of cells in
  // contact) within 0.5 % at 64 cells across; the issue asks for δ within 1 %.
  EXPECT_NEAR(r.interference, hertz.approach(), 1e-3 * hertz.approach());
  const double a_num = std::sqrt(r.contact_fraction * g.area() / pi);
  EXPECT_NEAR(a_num, a, 0.01 * a);
  const double p_max = *std::max_element(contact.pressure().begin(), contact.pressure().end());
  EXPECT_NEAR(p_max, hertz.peak_pressure(), 1e-3 * hertz.peak_pressure());
  EXPECT_NEAR(r.mean_pressure * g.area(), c.load, 1e-10 * c.load);
  // Outside the contact the surface follows Johnson's (3.42b) towards the far field.
  const std::size_t mid = cells / 2, off = 3 * c.n / 4;  // r = 1.5 a
  const double outside = hertz_outside(hertz, static_cast<double>(off) * dx);
  EXPECT_NEAR(contact.displacement()(mid + off, mid), outside, 2e-3 * outside);
  RecordProperty("outside_relative_error", std::to_string(contact.displacement()(mid + off, mid) / outside - 1.0));
  RecordProperty("approach_relative_error", std::to_string(r.interference / hertz.approach() - 1.0));
  RecordProperty("a_relative_error", std::to_string(a_num / a - 1.0));
  RecordProperty("p0_relative_error", std::to_string(p_max / hertz.peak_pressure() - 1.0));
  RecordProperty("iterations", std::to_string(r.iterations));
}

INSTANTIATE_TEST_SUITE_P(
    Spheres, FreeHertzTest,
    ::testing::Values(HertzCase{"pin", 3e-3, 1.0, effective_modulus(73e9, 0.17, 73e9, 0.17), 4.0, 64},
                      HertzCase{"unit", 1.0, 4.0 * std::pow(0.04, 3) / 3.0, 1.0, 3.0, 96},
                      HertzCase{"stiff", 0.05, 20.0, 150e9, 2.5, 128}),
    [](const auto& p) { return std::string(p.param.name); });

TEST(NormalContact, AFreeWindowTooSmallForItsContactIsRefused) {
  // The same sphere on a window narrower than its contact (1.5 a wide): the
  // pressure reaches the border, where the body is missing. Refused, not solved.
  const HertzContact hertz{1.0, 4.0 * std::pow(0.04, 3) / 3.0, 1.0};
  const double a = hertz.contact_radius();
  const Grid2D g = Grid2D::square(48, 1.5 * a);
  NormalContact contact(paraboloid(g, 1.0), 1.0, Boundary::Free);
  try {
    contact.solve_mean_pressure(hertz.load / g.area());
    FAIL() << "a contact reaching the window's edge must be refused";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("free boundary"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("edge"));
  }
  NormalContact inside(paraboloid(g, 1.0), 1.0, Boundary::Free);  // a tenth of the load: a = 0.46 a fits
  EXPECT_NO_THROW(inside.solve_mean_pressure(0.1 * hertz.load / g.area()));
}

TEST(NormalContact, AStopAskedForEndsTheSolveAtThatIterationAndOneNeverAskedChangesNothing) {
  // ContactOptions::stop is asked once an iteration (SIGTERM on a long solve);
  // a yes ends the solve with Interrupted there, a no leaves every bit alone.
  const Grid2D g = Grid2D::square(64, 1.0);
  NormalContact plain(paraboloid(g, 1.0), 1.0), asked(paraboloid(g, 1.0), 1.0), stopped(paraboloid(g, 1.0), 1.0);
  const ContactResult r = plain.solve_mean_pressure(1e-3, {1e-10, 1000});
  int questions = 0;
  ContactOptions no{1e-10, 1000};
  no.stop = [&questions] { return ++questions < 0; };
  const ContactResult s = asked.solve_mean_pressure(1e-3, no);
  EXPECT_EQ(questions, s.iterations + 1);  // once an iteration, the converged one too
  EXPECT_EQ(r.iterations, s.iterations);
  EXPECT_EQ(r.error, s.error);
  for (std::size_t k = 0; k < g.size(); ++k) ASSERT_EQ(plain.pressure()[k], asked.pressure()[k]) << k;

  ContactOptions yes{1e-10, 1000};
  questions = 0;
  yes.stop = [&questions] { return ++questions == 3; };
  try {
    stopped.solve_mean_pressure(1e-3, yes);
    FAIL() << "the stop was not heard";
  } catch (const Interrupted& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("stopped at iteration 2"));
  }
  EXPECT_EQ(questions, 3);
}
