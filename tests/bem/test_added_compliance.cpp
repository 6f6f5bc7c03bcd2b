// Normal contact with a compliance added to the half-space's (the implicit
// wear step of the pin-on-disc): exact solutions of the two in series.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

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
