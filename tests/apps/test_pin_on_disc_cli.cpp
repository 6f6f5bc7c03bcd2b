// The pin-on-disc keys as users meet them: the friction table carries
// its moving average, the disc its grooves, a [sweep.series] one table per
// series, and every bad value of a new key is refused with status 2 naming
// the key, the value and what is allowed, with nothing written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_pod_cli_");
const std::filesystem::path work = work_scratch.path();
const std::string pin_on_disc = "'" + std::string(WEARSCALE_SOURCE_DIR) + "/cases/pin_on_disc_si_oxide.toml'";
const std::string nonplanar = "'" + std::string(WEARSCALE_SOURCE_DIR) + "/cases/nonplanar.toml'";
const std::string small = " --set scale.macro.grid=32 --set scale.macro.distance=0.06";
}  // namespace

TEST(PinOnDiscCli, TheFrictionTableCarriesItsMovingAverageAndTheDiscItsGrooves) {
  const auto r = run_cli("run " + pin_on_disc + small + " --set materials.layer.thickness=0.5e-6 --out pod --json", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["results"]["grooves"]["value"].get<double>(), 1.0);
  EXPECT_THAT(j["results"]["mu_final"]["description"].get<std::string>(), HasSubstr("last 5 %"));
  const std::string csv = slurp(work / "pod" / "friction.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "distance_m,friction,friction_moving_average,pin_wear_m3,disc_wear_m3,contact_fraction,layer_share,grooves,"
            "pin_specific_wear_rate_mm3_per_N_per_m,disc_specific_wear_rate_mm3_per_N_per_m")
      << "one header line, then rows (pandas.read_csv reads it as is)";
  const auto notes = nlohmann::json::parse(slurp(work / "pod" / "friction.csv.json"));
  EXPECT_EQ(notes["rows"].get<std::size_t>(), static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n')) - 1);
  EXPECT_THAT(notes["notes"].dump(), HasSubstr("moving mean over 0.003 m"));  // a twentieth of 0.06 m without a tilt
  EXPECT_THAT(slurp(work / "pod" / "disc_profile.csv"), HasSubstr("x_m,worn_depth_m,through_layer"));
}

TEST(PinOnDiscCli, ASeriesSweepWritesOneTablePerSeriesAndTheTiltPeriodFramesMuFinal) {
  const auto r = run_cli("run " + nonplanar + small + " --set 'sweep.values=[0.02]' --out np --json", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["sweep"]["runs"].size(), 2u);
  EXPECT_EQ(j["sweep"]["runs"][1]["series"], "tilted");
  EXPECT_THAT(j["sweep"]["runs"][1]["results"]["mu_final"]["description"].get<std::string>(),
              HasSubstr("last whole tilt period (0.05 m)"));
  EXPECT_TRUE(fs::exists(work / "np" / "friction_vs_slope_layer_test=disc.csv"));
  EXPECT_TRUE(fs::exists(work / "np" / "friction_vs_slope_layer_test=tilted.csv"));
  EXPECT_TRUE(fs::exists(work / "np" / "layer_test=tilted" / "slope=0.02" / "friction.csv"));
}

struct BadKey {
  std::string name, args, key, value, allowed;
};
void PrintTo(const BadKey& b, std::ostream* os) { *os << b.name; }
class PinOnDiscCliBadKey : public ::testing::TestWithParam<BadKey> {};

TEST_P(PinOnDiscCliBadKey, ExitsWithStatus2NamingKeyValueAndRangeAndWritesNothing) {
  const auto& p = GetParam();
  const auto out = work / ("bad-" + p.name);
  const auto r = run_cli("run " + pin_on_disc + small + " --out '" + out.string() + "' " + p.args, work);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr(p.key));
  EXPECT_THAT(r.err, HasSubstr(p.value));
  EXPECT_THAT(r.err, HasSubstr(p.allowed));
  EXPECT_FALSE(fs::exists(out));
}

INSTANTIATE_TEST_SUITE_P(
    Keys, PinOnDiscCliBadKey,
    ::testing::Values(
        BadKey{"layer_test", "--set scale.macro.nonplanarity.layer_test=flat", "scale.macro.nonplanarity.layer_test",
               "\"flat\"", "allowed: \"disc\", \"tilted\""},
        BadKey{"track", "--set scale.macro.track=circular", "scale.macro.track", "\"circular\"",
               "allowed: \"averaged\", \"resolved\""},
        BadKey{"moving_average", "--set scale.macro.moving_average=-1", "scale.macro.moving_average", "-1",
               "allowed: > 0 m"},
        BadKey{"moving_average_unit", "--set 'scale.macro.moving_average=\"2 s\"'", "scale.macro.moving_average",
               "\"2 s\"", "has unit of s, expected m; allowed: > 0 m"},
        BadKey{"steps_per_period", "--set scale.macro.adaptive.steps_per_period=2",
               "scale.macro.adaptive.steps_per_period", "2", "allowed: integer [4, 10000]"},
        BadKey{"rtol", "--set scale.macro.adaptive.rtol=0", "scale.macro.adaptive.rtol", "0", "allowed: (0, 1)"},
        BadKey{"resolved_period", "--set scale.macro.track=resolved --set scale.macro.nonplanarity.period=0.05",
               "scale.macro.nonplanarity.period", "0.05", "once per revolution"},
        BadKey{"series_key", "--set sweep.key=scale.macro.grid --set 'sweep.values=[32]' "
                             "--set sweep.series.key=scale.macro.nothing --set 'sweep.series.values=[1]'",
               "sweep.series.key", "\"scale.macro.nothing\"", "a key of the case"}),
    [](const auto& p) { return p.param.name; });
