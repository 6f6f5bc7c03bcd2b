// The pin-on-disc wear model (§9.3.2) against the macroscale section of
// VERIFICATION.md, on the thesis setup (n = 128, L = 2 mm, R = 3 mm, 1 N,
// 8 mm/s, dt = 0.02 s) over shortened sliding distances (the full 0.5 m runs
// are the case files and the `long` tests).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "wearscale/core/errors.hpp"
#include "wearscale/materials/shipped_data.hpp"
#include "wearscale/tribometer/adaptive_wear.hpp"
#include "wearscale/tribometer/pin_on_disc.hpp"

using namespace wearscale;
using namespace wearscale::tribometer;

namespace {
const materials::StrengthLaw si(materials::shipped_table("thesis", "Si"));
const materials::StrengthLaw sio2(materials::shipped_table("thesis", "SiO2"));

PinOnDiscSetup thesis(double layer, double distance) {
  PinOnDiscSetup s;
  s.on_layer = materials::interface_law("SiO2", sio2, "SiO2", sio2);
  s.on_substrate = materials::interface_law("SiO2", sio2, "Si", si);
  s.layer_thickness = layer;
  s.distance = distance;
  return s;
}

std::vector<PinOnDiscSample> run(const PinOnDiscSetup& s) {
  PinOnDisc model(s);
  std::vector<PinOnDiscSample> out;
  model.run([&](const PinOnDiscSample& x) { out.push_back(x); });
  return out;
}

double mean_friction(const std::vector<PinOnDiscSample>& x) {
  double sum = 0.0;
  for (const auto& e : x) sum += e.friction;
  return sum / static_cast<double>(x.size());
}

// First distance at which the pin touches the substrate.
double transition(const std::vector<PinOnDiscSample>& x) {
  for (const auto& e : x)
    if (e.substrate_contact > 0.0) return e.distance;
  return std::numeric_limits<double>::infinity();
}
}  // namespace

TEST(PinOnDisc, BareSiliconSlidesAtMuSiThroughout) {
  for (const auto& e : run(thesis(0.0, 0.1))) ASSERT_NEAR(e.friction, 0.14, 0.005) << "s = " << e.distance;
}

TEST(PinOnDisc, BulkSilicaSlidesAtMuSiO2Throughout) {
  const auto x = run(thesis(std::numeric_limits<double>::infinity(), 0.1));
  for (const auto& e : x) ASSERT_NEAR(e.friction, 0.84, 0.005) << "s = " << e.distance;
  // Like on like: pin and disc wear alike (9.24)-(9.25).
  EXPECT_NEAR(x.back().pin_wear, x.back().disc_wear, 1e-6 * x.back().disc_wear);
}

TEST(PinOnDisc, OneMicronOfOxideWearsThroughNearThreeCentimetres) {
  const auto x = run(thesis(1e-6, 0.1));
  const double s_t = transition(x);
  EXPECT_GT(s_t, 0.02);  // thesis: μ ≈ 0.84 until about s = 0.03 m (Fig. 9.20)
  EXPECT_LT(s_t, 0.06);
  for (const auto& e : x) {
    if (e.distance < 0.9 * s_t) {
      ASSERT_NEAR(e.friction, 0.84, 0.005);
    }
  }
  EXPECT_LT(x.back().friction, 0.4);  // falling toward μ_Si
  EXPECT_GT(x.back().friction, 0.14);
}

TEST(PinOnDisc, PinWearSlowsAtTheTransitionWhileTotalWearRateStaysNearlyConstant) {
  const auto x = run(thesis(1e-6, 0.1));
  const double s_t = transition(x);
  auto at = [&](double s) {
    for (const auto& e : x)
      if (e.distance >= s) return e;
    return x.back();
  };
  const auto a = at(0.25 * s_t), b = at(0.75 * s_t), c = at(0.08), d = at(0.1);
  const double pin_before = (b.pin_wear - a.pin_wear) / (b.distance - a.distance);
  const double pin_after = (d.pin_wear - c.pin_wear) / (d.distance - c.distance);
  const double total_before = (b.pin_wear + b.disc_wear - a.pin_wear - a.disc_wear) / (b.distance - a.distance);
  const double total_after = (d.pin_wear + d.disc_wear - c.pin_wear - c.disc_wear) / (d.distance - c.distance);
  EXPECT_LT(pin_after, 0.5 * pin_before);
  // F/p_crit of the interfaces: 1/8.5 GPa⁻¹ on oxide, 1/10.6 GPa⁻¹ on Si: within 20 %.
  EXPECT_NEAR(total_after / total_before, 1.0, 0.2);
  EXPECT_NEAR(total_before, 1.0 / 8.5e9, 0.01 / 8.5e9);  // dV/ds = Σ p/p_crit ΔA = F/p_crit (9.21)
}

TEST(PinOnDisc, ThickerOxideDelaysTheTransitionRaisesMuAndSparesTheDisc) {
  const auto thin = run(thesis(0.5e-6, 0.1)), thick = run(thesis(1e-6, 0.1));
  EXPECT_LT(transition(thin), transition(thick));
  EXPECT_LT(mean_friction(thin), mean_friction(thick));
  EXPECT_GT(thin.back().disc_wear, thick.back().disc_wear);
}

TEST(PinOnDisc, AdaptiveIntegrationFollowsTheExplicitCurveWithFewerSolves) {
  const auto setup = thesis(0.5e-6, 0.05);
  const auto explicit_run = run(setup);
  PinOnDisc model(setup);
  std::vector<PinOnDiscSample> adaptive;
  run_adaptive(model, {}, [&](const PinOnDiscSample& x) { adaptive.push_back(x); });
  EXPECT_NEAR(adaptive.back().distance, 0.05, 1e-12);
  EXPECT_LT(model.contact_solves(), static_cast<int>(explicit_run.size()));
  // Same wear and the same transition, to a few %.
  const double v_exp = explicit_run.back().pin_wear + explicit_run.back().disc_wear;
  const double v_ada = adaptive.back().pin_wear + adaptive.back().disc_wear;
  EXPECT_NEAR(v_ada, v_exp, 0.03 * v_exp);
  EXPECT_NEAR(transition(adaptive), transition(explicit_run), 0.005);
  RecordProperty("explicit_solves", std::to_string(explicit_run.size()));
  RecordProperty("adaptive_solves", std::to_string(model.contact_solves()));
}

TEST(PinOnDisc, BadParametersAreRefusedByName) {
  auto s = thesis(-1e-6, 0.1);
  try {
    PinOnDisc m(s);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("layer_thickness"));
  }
  s = thesis(1e-6, 0.1);
  s.on_layer = {};
  EXPECT_THROW(PinOnDisc{s}, InputError);
}
