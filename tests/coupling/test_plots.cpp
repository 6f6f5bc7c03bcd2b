// Legends of the sweep figures: a run folder's name as a reader would write it.
#include <gtest/gtest.h>

#include "wearscale/coupling/plots.hpp"

using wearscale::coupling::legend_label;

TEST(Plots, LegendsNameTheOxideThicknessInMicrometres) {
  EXPECT_EQ(legend_label("thickness=5e-07"), "h = 0.5 µm");
  EXPECT_EQ(legend_label("thickness=3e-06"), "h = 3 µm");
  EXPECT_EQ(legend_label("thickness=0"), "h = 0 (no oxide)");
  EXPECT_EQ(legend_label("thickness=inf"), "h = ∞ (bulk oxide)");
}

TEST(Plots, OtherLegendsKeepTheirKeyAndValue) {
  EXPECT_EQ(legend_label("slope=0.02 layer_test=disc"), "slope = 0.02, layer_test = disc");
  EXPECT_EQ(legend_label("pin-on-disc-si-oxide"), "pin-on-disc-si-oxide");
  EXPECT_EQ(legend_label("thickness=thick"), "thickness = thick") << "not a number: as it is";
}
