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

// The sweep figures' titles state the parameters the case sets, in the units a
// reader would write, and leave a swept key to the legends.
TEST(Plots, SweepTitlesStateTheLoadTheVelocityThePinAndTheSweptKey) {
  const auto c = wearscale::Config::from_string(
      "[materials]\npin = \"SiO2\"\ndisc = \"Si\"\n"
      "[scale.macro]\npin_radius = \"3 mm\"\nnormal_load = \"1 N\"\nvelocity = \"8 mm/s\"\n");
  EXPECT_EQ(wearscale::coupling::sweep_title(c, "oxide-thickness-sweep", "materials.layer.thickness"),
            "oxide-thickness-sweep\nSiO2 pin on Si disc, R = 3 mm, F_N = 1 N, v = 8 mm/s; "
            "swept: materials.layer.thickness");
  EXPECT_EQ(wearscale::coupling::sweep_title(c, "loads", "scale.macro.normal_load", "scale.macro.velocity"),
            "loads\nSiO2 pin on Si disc, R = 3 mm; swept: scale.macro.normal_load, series: scale.macro.velocity");
  EXPECT_EQ(wearscale::coupling::sweep_title(wearscale::Config::from_string(""), "bare", "k"), "bare\nswept: k")
      << "nothing set, nothing stated";
}
