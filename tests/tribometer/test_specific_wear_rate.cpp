// The specific wear rate k = V / (F_N s) of Archard's law in mm³/(N·m), as
// tribologists quote it.
#include <gtest/gtest.h>

#include <cmath>

#include "wearscale/tribometer/specific_wear_rate.hpp"

using wearscale::tribometer::specific_wear_rate;

TEST(SpecificWearRate, IsTheWornVolumeInCubicMillimetresPerNewtonAndMetreOfSliding) {
  // By hand: 2.941176471e-11 m³ = 2.941176471e-2 mm³ worn under 1 N over 0.5 m
  // (the bulk SiO2 disc of the oxide sweep): k = 0.02941176471 / (1 × 0.5) = 0.05882352942 mm³/(N·m).
  EXPECT_NEAR(specific_wear_rate(2.941176471e-11, 1.0, 0.5), 0.05882352942, 1e-12);
  // 1 mm³ under 10 N over 100 m: 1e-3 mm³/(N·m).
  EXPECT_NEAR(specific_wear_rate(1e-9, 10.0, 100.0), 1e-3, 1e-18);
}

TEST(SpecificWearRate, IsUndefinedBeforeAnySliding) {
  EXPECT_TRUE(std::isnan(specific_wear_rate(0.0, 1.0, 0.0)));
  EXPECT_TRUE(std::isnan(specific_wear_rate(1e-12, 0.0, 1.0)));
}
