// The figures' words: legends and titles name a run's parameters as a
// reader writes them, and no name, path or value reaches a figure's script:
// a kind's script is the same text whatever the run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scratch_dir.hpp"
#include "wearscale/coupling/plots.hpp"

using wearscale::Config;
using wearscale::coupling::parameter_words;

namespace {
Config oxide_case(const std::string& thickness = "\"1 um\"") {
  return Config::from_string("[materials]\npin = \"SiO2\"\ndisc = \"Si\"\nlayer = { material = \"SiO2\", thickness = " +
                             thickness + " }\n[scale.macro]\npin_radius = \"3 mm\"\nnormal_load = \"1 N\"\n"
                             "velocity = \"8 mm/s\"\n");
}
const Config oxide = oxide_case();
}  // namespace

TEST(Plots, LegendsNameTheOxideLayerAndItsThicknessInMicrometres) {
  EXPECT_EQ(parameter_words(oxide, "materials.layer.thickness", "5e-07"), "SiO2 layer 0.5 µm");
  EXPECT_EQ(parameter_words(oxide, "materials.layer.thickness", "3e-06"), "SiO2 layer 3 µm");
  EXPECT_EQ(parameter_words(oxide, "materials.layer.thickness", "1 um"), "SiO2 layer 1 µm");
  EXPECT_EQ(parameter_words(oxide, "materials.layer.thickness", "0"), "no SiO2 layer");
  EXPECT_EQ(parameter_words(oxide, "materials.layer.thickness", "inf"), "bulk SiO2");
}

TEST(Plots, LegendsNameThePinOnDiscKeysInWordsWithTheirUnits) {
  EXPECT_EQ(parameter_words(oxide, "scale.macro.normal_load", "2"), "load 2 N");
  EXPECT_EQ(parameter_words(oxide, "scale.macro.velocity", "0.016"), "speed 16 mm/s");
  EXPECT_EQ(parameter_words(oxide, "scale.macro.pin_radius", "1.5 mm"), "pin radius 1.5 mm");
  EXPECT_EQ(parameter_words(oxide, "scale.macro.nonplanarity.slope", "0.02"), "disc tilt 0.02");
}

TEST(Plots, OtherKeysKeepTheirLastPartAndValue) {
  EXPECT_EQ(parameter_words(oxide, "scale.macro.nonplanarity.layer_test", "tilted"), "layer test tilted");
  EXPECT_EQ(parameter_words(oxide, "wearmap.rough.hurst", "0.8"), "hurst 0.8");
  EXPECT_EQ(parameter_words(oxide, "materials.layer.thickness", "thick"), "thickness thick") << "not a number: as it is";
}

TEST(Plots, LengthsAreWrittenInTheUnitAReaderUses) {
  using wearscale::coupling::length_words;
  EXPECT_EQ(length_words(5e-7), "0.5 µm");
  EXPECT_EQ(length_words(3e-3), "3 mm");
  EXPECT_EQ(length_words(2e-8), "20 nm");
  EXPECT_EQ(length_words(0.5), "500 mm");
  EXPECT_EQ(length_words(2.0), "2 m");
  EXPECT_EQ(length_words(0.0), "0");
}

// Each run's figure is titled by its parameters, so that the six runs of the
// oxide sweep are told apart; a sweep's figures leave the swept key to the legends.
TEST(Plots, ARunsTitleNamesItsParametersInWords) {
  EXPECT_EQ(wearscale::coupling::run_title(oxide, "oxide"),
            "oxide\nSiO2 pin on Si disc, SiO2 layer 1 µm, pin radius 3 mm, load 1 N, speed 8 mm/s");
  EXPECT_EQ(wearscale::coupling::run_title(oxide_case("inf"), "oxide"),
            "oxide\nSiO2 pin on Si disc, bulk SiO2, pin radius 3 mm, load 1 N, speed 8 mm/s");
  // A name of 70 000 characters is cut to 150 (and an ellipsis): the parameters still fit in the figure's title.
  std::string cut(150, 'x');
  cut.append("…\nSiO2 pin on Si disc, SiO2 layer 1 µm, pin radius 3 mm, load 1 N, speed 8 mm/s");
  EXPECT_EQ(wearscale::coupling::run_title(oxide, std::string(70000, 'x')), cut);
}

TEST(Plots, SweepTitlesStateTheFixedParametersAndWhatIsSweptInWords) {
  EXPECT_EQ(wearscale::coupling::sweep_title(oxide, "oxide-thickness-sweep", "materials.layer.thickness"),
            "oxide-thickness-sweep\nSiO2 pin on Si disc, pin radius 3 mm, load 1 N, speed 8 mm/s; "
            "swept: SiO2 layer thickness");
  EXPECT_EQ(wearscale::coupling::sweep_title(oxide, "loads", "scale.macro.normal_load", "scale.macro.velocity"),
            "loads\nSiO2 pin on Si disc, SiO2 layer 1 µm, pin radius 3 mm; swept: load; series: speed");
  EXPECT_EQ(wearscale::coupling::sweep_title(Config::from_string(""), "bare", "a.k"), "bare\nswept: k")
      << "nothing set, nothing stated";
}

// The security of the figures by construction: whatever the titles, legends
// and file names (a user's, hostile or not), the script of a kind is one
// text; they reach it only through its texts file.
TEST(Plots, AFiguresScriptIsTheSameTextWhateverItsTitlesLegendsAndFiles) {
  using namespace wearscale::coupling;
  const ScratchDir scratch("wearscale_plot_script_");
  const auto hostile = scratch.file("x'; system('touch PWNED'); print('");
  const auto plain = scratch.file("plain");
  for (const auto& d : {hostile, plain}) {
    std::filesystem::create_directories(d / "run `id` $(id)");
    std::ofstream(d / "run `id` $(id)" / "friction.csv") << "distance_m,pin_wear_m3,disc_wear_m3\n0.0,0.0,0.0\n";
    std::ofstream(d / "run `id` $(id)" / "disc_profile.csv") << "x_m,worn_depth_m\n0.0,0.0\n";
  }
  const std::string evil = "\"'; system(\"touch PWNED\") @ARG0 `id` $(id) \\\n#";
  const auto a = friction_figure("f", evil, {{evil, hostile / "run `id` $(id)" / "friction.csv"}}, hostile);
  const auto b = friction_figure("f", "title", {{"label", plain / "run `id` $(id)" / "friction.csv"}}, plain);
  EXPECT_EQ(figure_script(a), figure_script(b));
  EXPECT_EQ(figure_script(a).find("PWNED"), std::string::npos);
  EXPECT_EQ(figure_script(a).find("`id`"), std::string::npos);
  const auto c = disc_profiles_figure("d", evil, {{evil, hostile / "run `id` $(id)" / "disc_profile.csv"}}, 1e-6, hostile);
  const auto d = disc_profiles_figure("d", "t", {{"l", plain / "run `id` $(id)" / "disc_profile.csv"}}, 0.0, plain);
  EXPECT_EQ(figure_script(c), figure_script(d));
  EXPECT_EQ(a.data.front(), std::filesystem::path("run `id` $(id)") / "friction.csv")
      << "data named relative to the figure's folder";
}

// The disc's profiles are drawn against the x of disc_profile.csv (in mm):
// the same x as run.h5's fields and final_surfaces.xdmf (docs/fields.md).
TEST(Plots, TheDiscProfilesAreDrawnAgainstTheTablesX) {
  const ScratchDir scratch("wearscale_plot_profile_");
  std::ofstream(scratch.file("disc_profile.csv")) << "x_m,worn_depth_m,through_layer\n0.0,0.0,0.0\n";
  const auto f = wearscale::coupling::disc_profiles_figure("disc_profiles", "t", {{"l", scratch.file("disc_profile.csv")}},
                                                           0.0, scratch.path());
  EXPECT_NE(f.script.find("using (column(\"x_m\")*1e3):(-column(\"worn_depth_m\")*1e6)"), std::string::npos);
}
