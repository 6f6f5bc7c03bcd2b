// Restarting the pin-on-disc model from a saved state (what a checkpoint
// holds): the explicit integrator ends bit for bit where an uninterrupted
// run ends; the adaptive one within its error tolerance. And the numerical
// guards of the loop: NaN/Inf stop it with a NumericalError naming the
// quantity, the step and the distance.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "wearscale/core/errors.hpp"
#include "wearscale/io/checkpoint.hpp"
#include "wearscale/io/shipped_data.hpp"
#include "wearscale/tribometer/adaptive_wear.hpp"
#include "wearscale/tribometer/pin_on_disc.hpp"
#include "adaptive_restart.hpp"
#include "thesis_pin_on_disc.hpp"

using namespace wearscale;
using namespace wearscale::tribometer;

namespace {
// A reduced thesis setup (32 × 32 cells) through the oxide transition at 0.5 µm.
PinOnDiscSetup small(double distance) {
  PinOnDiscSetup s = test_support::thesis_setup(0.5e-6);
  s.grid = 32;
  s.distance = distance;
  return s;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_identical(const std::vector<PinOnDiscSample>& a, const std::vector<PinOnDiscSample>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    ASSERT_TRUE(same_bits(a[k].distance, b[k].distance)) << k;
    ASSERT_TRUE(same_bits(a[k].friction, b[k].friction)) << k;
    ASSERT_TRUE(same_bits(a[k].pin_wear, b[k].pin_wear)) << k;
    ASSERT_TRUE(same_bits(a[k].disc_wear, b[k].disc_wear)) << k;
    ASSERT_TRUE(same_bits(a[k].max_pressure, b[k].max_pressure)) << k;
    ASSERT_EQ(a[k].iterations, b[k].iterations) << k;
  }
}

}  // namespace

TEST(PinOnDiscRestart, ExplicitRunFromASavedStateEndsBitForBitAsAnUninterruptedOne) {
  const auto setup = small(0.03);  // 188 steps, through the transition near 0.015 m
  PinOnDisc whole(setup);
  std::vector<PinOnDiscSample> reference;
  whole.run([&](const PinOnDiscSample& x) { reference.push_back(x); });

  PinOnDisc first(setup);
  std::vector<PinOnDiscSample> samples;
  for (int k = 0; k < 77; ++k) samples.push_back(first.step());
  CheckpointState saved;
  first.save(saved);

  PinOnDisc second(setup);  // a new process: a fresh model, restored
  second.restore(saved);
  EXPECT_EQ(second.steps(), 77);
  second.run([&](const PinOnDiscSample& x) { samples.push_back(x); });
  expect_identical(samples, reference);
  EXPECT_EQ(second.contact_solves(), whole.contact_solves());
  for (std::size_t k = 0; k < whole.pin_surface().size(); ++k)
    ASSERT_TRUE(same_bits(second.pin_surface()[k], whole.pin_surface()[k])) << k;
}

TEST(PinOnDiscRestart, AdaptiveRunFromAStateSavedAtARestartEndsBitForBitAsAnUninterruptedOne) {
  AdaptiveOptions options;
  options.restart_every = 5;
  const auto run = test_support::adaptive_restart(small(0.03), options, 10);
  ASSERT_GT(run.uninterrupted_steps, 15) << "the test needs a run of several restart segments";
  EXPECT_EQ(run.stopped_at.steps, 10);
  EXPECT_NEAR(run.resumed.back().distance, 0.03, 1e-12);
  expect_identical(run.resumed, run.uninterrupted);
}

TEST(PinOnDiscRestart, AStateOfAnotherGridIsRefused) {
  PinOnDisc a(small(0.01));
  CheckpointState saved;
  a.save(saved);
  auto other = small(0.01);
  other.grid = 64;
  PinOnDisc b(other);
  try {
    b.restore(saved);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("a pin-on-disc state of 1024 pin cells"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("the case has 4096 pin cells (64×64)"));
  }
  // A pin of the right size with a disc profile of another length: the message says which part differs.
  CheckpointState wrong_disc;
  b.save(wrong_disc);
  wrong_disc.put("disc_profile", std::vector<double>(32, 0.0));
  try {
    b.restore(wrong_disc);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("4096 pin cells, 32 disc profile values"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("and 64 disc profile values"));
  }
}

TEST(PinOnDiscGuards, AnInfiniteWearRateStopsTheRunNamingTheQuantity) {
  auto setup = small(0.01);
  setup.on_layer.p_crit = 1e-300;  // p/p_crit overflows to +inf
  PinOnDisc model(setup);
  try {
    model.run([](const PinOnDiscSample&) {});
    FAIL() << "an infinite wear rate must stop the run";
  } catch (const NumericalError& e) {
    EXPECT_EQ(e.solver(), "tribometer/pin-on-disc");
    EXPECT_EQ(e.quantity(), "friction and wear rates");
    EXPECT_THAT(e.detail(), ::testing::HasSubstr("inf"));
    EXPECT_THAT(e.detail(), ::testing::HasSubstr("at s = 0 m"));
  }
}

TEST(PinOnDiscGuards, ANonFiniteStateInTheAdaptiveIntegratorIsANumericalError) {
  auto setup = small(0.01);
  PinOnDisc model(setup);
  std::vector<double> y = model.state();
  y[5] = std::nan("");
  std::vector<double> dyds(y.size());
  PinOnDiscSample sample;
  try {
    model.derivative(0.0, y.data(), dyds.data(), sample);
    FAIL() << "a NaN height must stop the solve";
  } catch (const NumericalError& e) {
    EXPECT_EQ(e.quantity(), "surface heights");
    EXPECT_THAT(e.detail(), ::testing::HasSubstr("cell (0, 5)"));
  }
}

TEST(PinOnDiscGuards, AnImplicitStageWhoseContactDoesNotConvergeLeavesTheModelAsItWas) {
  // The adaptive integrator then retries with a shorter step (ARKODE's
  // recoverable convergence failure): nothing of the failed attempt may stay.
  auto setup = small(0.01);
  setup.max_iterations = 2;  // every solve runs out of iterations
  PinOnDisc model(setup);
  const auto before = model.state();
  const std::vector<double> warm(model.contact().pressure().begin(), model.contact().pressure().end());
  std::vector<double> z(before.size()), rate(before.size());
  PinOnDiscSample sample;
  try {
    model.solve_stage(1e-3, before.data(), 1e-3, z.data(), rate.data(), sample);
    FAIL() << "the stage cannot be solved in two iterations";
  } catch (const StageNotSolved& e) {
    EXPECT_EQ(e.quantity(), "contact at s = 0.001 m");
    EXPECT_THAT(e.detail(), ::testing::HasSubstr("no convergence"));
  }
  EXPECT_EQ(model.state(), before);
  EXPECT_TRUE(std::equal(warm.begin(), warm.end(), model.contact().pressure().begin()));
}
