// Normal contact with a compliance added to the half-space's (the implicit
// wear step of the pin-on-disc): exact solutions of the two in series.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "wearscale/bem/normal_contact.hpp"

using namespace wearscale;
using namespace wearscale::bem;
using std::numbers::pi;

namespace {
// A uniform compliance w per cell: u += w p (a Winkler layer on the half-space).
struct Winkler final : bem::AddedCompliance {
  double w = 0.0;
  void add(const RealField& p, double scale, RealField& u) const override {
    for (std::size_t k = 0; k < p.size(); ++k) u[k] += scale * w * p[k];
  }
  double quadratic_form(const RealField& t) const override {
    double sum = 0.0;
    for (double v : t) sum += w * v * v;
    return sum;
  }
};

// Both methods take the added compliance (the preconditioner stays the half-space's inverse).
class CompliantContact : public ::testing::TestWithParam<ContactMethod> {};
}  // namespace

TEST_P(CompliantContact, AWavySurfaceInFullContactSeesTheHalfSpaceAndTheLayerInSeries) {
  // h = Δ cos(qx) pressed into full contact: p = p0 + p1 cos(qx) with
  // p1 = Δ / (2/(E* q) + w); with w = 2/(E* q) the amplitude halves.
  const auto g = Grid2D::square(64, 1.0);
  const double e_star = 1.0, q = 2.0 * pi / g.lx, delta = 1e-3;
  RealField h(g);
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) h(i, j) = delta * std::cos(q * g.x(i));
  Winkler layer;
  layer.w = 2.0 / (e_star * q);
  NormalContact contact(h, e_star);
  contact.set_added_compliance(&layer);
  const double p0 = 10.0 * delta * e_star * q;  // well above the amplitude: full contact
  contact.solve_mean_pressure(p0, {1e-12, 1000, GetParam()});
  const double p1 = delta / (2.0 / (e_star * q) + layer.w);
  for (std::size_t i = 0; i < g.nx; ++i)
    ASSERT_NEAR(contact.pressure()(i, 0), p0 + p1 * std::cos(q * g.x(i)), 1e-9 * p0) << i;
  contact.set_added_compliance(nullptr);  // without it: Westergaard's full-contact amplitude Δ E* q / 2
  contact.solve_mean_pressure(p0, {1e-12, 1000, GetParam()});
  EXPECT_NEAR(contact.pressure()(0, 0), p0 + delta * e_star * q / 2.0, 1e-9 * p0);
}

TEST_P(CompliantContact, ARigidBodyOnALayerAloneCarriesThePressureOfAWinklerFoundation) {
  // A half-space a million times stiffer than the layer (its share: ~1e-6 of
  // the pressure): p = (h − d)/w where
  // h > d, with d set by the load (found here by bisection).
  const auto g = Grid2D::square(32, 1.0);
  const double radius = 2.0;
  RealField h(g);
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) {
      const double x = g.x(i) - 0.5, y = g.y(j) - 0.5;
      h(i, j) = -(x * x + y * y) / (2.0 * radius);
    }
  Winkler layer;
  layer.w = 1.0;
  NormalContact contact(h, 1e6);
  contact.set_added_compliance(&layer);
  const double p0 = 5e-3;
  contact.solve_mean_pressure(p0, {1e-12, 5000, GetParam()});
  auto mean_at = [&](double d) {
    double sum = 0.0;
    for (double v : h) sum += std::max(v - d, 0.0) / layer.w;
    return sum / static_cast<double>(h.size());
  };
  double lo = -1.0, hi = 0.0;
  for (int k = 0; k < 200; ++k) (mean_at(0.5 * (lo + hi)) > p0 ? lo : hi) = 0.5 * (lo + hi);
  const double d = 0.5 * (lo + hi);
  double worst = 0.0;
  for (std::size_t k = 0; k < h.size(); ++k)
    worst = std::max(worst, std::abs(contact.pressure()[k] - std::max(h[k] - d, 0.0) / layer.w));
  EXPECT_LT(worst, 2e-6 * *std::max_element(contact.pressure().begin(), contact.pressure().end()));
}

INSTANTIATE_TEST_SUITE_P(Methods, CompliantContact,
                         ::testing::Values(ContactMethod::PreconditionedCG, ContactMethod::TwoLevelCG,
                                           ContactMethod::PolonskyKeer),
                         [](const ::testing::TestParamInfo<ContactMethod>& method) {
                           return method.param == ContactMethod::PreconditionedCG ? "Preconditioned"
                                  : method.param == ContactMethod::TwoLevelCG     ? "TwoLevel"
                                                                                  : "PolonskyKeer";
                         });

namespace {
// A compliance w per cell that differs across the grid (a soft layer on half
// the surface, none on the other: the pin on oxide and on substrate), with the
// preconditioner (κ + w)⁻¹ that inverts it exactly and K by its diagonal κ.
struct PatchyWinkler final : bem::AddedCompliance {
  std::vector<double> w;
  double kappa = 0.0;
  mutable int applied = 0;
  void add(const RealField& p, double scale, RealField& u) const override {
    for (std::size_t k = 0; k < p.size(); ++k) u[k] += scale * w[k] * p[k];
  }
  double quadratic_form(const RealField& t) const override {
    double sum = 0.0;
    for (std::size_t k = 0; k < t.size(); ++k) sum += w[k] * t[k] * t[k];
    return sum;
  }
  bool has_preconditioner() const override { return kappa > 0.0; }
  void precondition(const RealField& r, RealField& z) const override {
    ++applied;
    for (std::size_t k = 0; k < r.size(); ++k) z[k] = r[k] / (kappa + w[k]);
  }
  std::vector<double> diagonal;  // 1/(κ + w)
  std::span<const double> precondition_diagonal() const override { return diagonal; }
};
}  // namespace

TEST(AddedCompliancePreconditioner, GivesTheSameContactInFewerIterationsThanSOrNone) {
  // A sphere on a half-space whose left half carries a layer 100 times softer
  // than a cell of the half-space: S (the half-space's inverse) does not fit
  // K + A there; (κ + w)⁻¹ does.
  const auto g = Grid2D::square(64, 1.0);
  const double e_star = 1.0, radius = 0.5;
  RealField h(g);
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) {
      const double x = g.x(i) - 0.5, y = g.y(j) - 0.5;
      h(i, j) = -(x * x + y * y) / (2.0 * radius);
    }
  NormalContact contact(h, e_star);
  PatchyWinkler layer;
  const double kappa = contact.body().self_compliance();
  layer.kappa = kappa;
  layer.w.assign(g.size(), 0.0);
  for (std::size_t i = 0; i < g.nx / 2; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) layer.w[g.index(i, j)] = 100.0 * kappa;
  for (double w : layer.w) layer.diagonal.push_back(1.0 / (kappa + w));
  contact.set_added_compliance(&layer);
  const double p0 = 2e-3;
  const auto plain = contact.solve_mean_pressure(p0, {1e-10, 5000, ContactMethod::PolonskyKeer});
  const RealField reference = contact.pressure();
  EXPECT_EQ(layer.applied, 0);  // not asked without a preconditioned method
  contact.reset();
  const auto own = contact.solve_mean_pressure(p0, {1e-10, 5000, ContactMethod::PreconditionedCG});
  EXPECT_EQ(layer.applied, own.iterations);  // every iteration but the converged one
  double worst = 0.0, peak = 0.0;
  for (std::size_t k = 0; k < h.size(); ++k) {
    worst = std::max(worst, std::abs(contact.pressure()[k] - reference[k]));
    peak = std::max(peak, reference[k]);
  }
  EXPECT_LT(worst, 1e-6 * peak);
  EXPECT_LT(own.iterations, plain.iterations);
  layer.kappa = 0.0;  // no preconditioner of its own: the solver's S
  contact.reset();
  const auto s = contact.solve_mean_pressure(p0, {1e-10, 5000, ContactMethod::PreconditionedCG});
  EXPECT_LT(own.iterations, s.iterations);
  RecordProperty("iterations_plain", plain.iterations);
  RecordProperty("iterations_s", s.iterations);
  RecordProperty("iterations_own", own.iterations);
}
