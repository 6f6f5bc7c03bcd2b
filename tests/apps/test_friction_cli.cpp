// `wearscale contact --friction ...`: frictional contact from flags and case
// files (Appendix A), its fields for ParaView, and bad input → status 2.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <numbers>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_friction_cli_");
const std::filesystem::path work = work_scratch.path();
const std::string friction_case = "'" + std::string(WEARSCALE_SOURCE_DIR) + "/cases/frictional_contact.toml'";
// The Mindlin case of Fig. A.4a (n = 243, E = 1, ν = 0.5, μ = 0.5, L = 1, R = 10, p_N,0 = 1.5e-4).
const std::string sphere = "contact --set contact.grid=243 --set contact.size=1 --set contact.sphere.radius=10 "
                           "--set contact.young=1 --poisson 0.5 --pressure 1.5e-4 ";
const std::string mindlin = sphere + "--friction coulomb --mu 0.5 ";
}  // namespace

TEST(FrictionCli, MindlinFromFlagsHasTheCattaneoMindlinStickZone) {
  const auto r = run_cli(mindlin + "--tangential-pressure 4e-5 --out mindlin --json", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out)["results"];
  EXPECT_NEAR(j["mean_tangential_pressure"]["value"].get<double>(), 4e-5, 1e-15);
  // c = a (1 − Q/μP)^(1/3), a = (3PR/4E*)^(1/3) with E* = 4/3: within 1 % (the
  // summit at the cell's centre, between grid points here).
  const double a = std::cbrt(3.0 * 1.5e-4 * 10.0 / (4.0 * 4.0 / 3.0)), c = a * std::cbrt(1.0 - 4e-5 / 7.5e-5);
  EXPECT_NEAR(std::sqrt(j["stick_fraction"]["value"].get<double>() / std::numbers::pi), c, 0.01 * c);
  EXPECT_EQ(j["full_sliding"]["value"], 0.0);
  EXPECT_LT(j["error"]["value"].get<double>(), 1e-10);
}

TEST(FrictionCli, WritesTractionsStickSlipDisplacementsAndStresses) {
  const auto r = run_cli(mindlin + "--tangential-pressure 4e-5 --tensile-strength 1e-3 "
                                   "--set 'contact.stress_depths=[0.01, 0.05]' --out fields",
                         work);
  ASSERT_EQ(r.status, 0) << r.err;
  const wearscale::H5Reader h5(work / "fields" / "contact.h5");
  for (const char* d : {"/fields/pressure", "/fields/traction_x", "/fields/traction_y", "/fields/stick_slip",
                        "/fields/displacement", "/fields/displacement_x", "/fields/slip_x", "/stress/surface/sigma_I",
                        "/stress/surface/tau_max", "/stress/depth_1/sigma_I", "/stress/depth_1/tau_max"})
    EXPECT_TRUE(h5.exists(d)) << d;
  const auto map = h5.read_field("/fields/stick_slip");
  double stick = 0.0, slip = 0.0;
  for (double v : map) {
    stick += v == 1.0 ? 1.0 : 0.0;
    slip += v == 2.0 ? 1.0 : 0.0;
  }
  EXPECT_GT(stick, 0.0);
  EXPECT_GT(slip, 0.0);
  const std::string xdmf = slurp(work / "fields" / "contact.xdmf");
  for (const char* name : {"stick_slip", "p_x", "sigma_I", "u_x", "tau_max_depth_1"})
    EXPECT_THAT(xdmf, HasSubstr(name));
  EXPECT_THAT(slurp(work / "fields" / "clusters.csv"), HasSubstr("crack_initiation"));
}

TEST(FrictionCli, TheFigA5CaseNeverExceedsTheTrescaStrength) {
  const auto r = run_cli("contact " + friction_case +
                             " --set contact.grid=128 --set contact.rough.k_s=64 --out tresca --json",
                         work);
  ASSERT_EQ(r.status, 0) << r.err;
  const wearscale::H5Reader h5(work / "tresca" / "contact.h5");
  const auto px = h5.read_field("/fields/traction_x"), py = h5.read_field("/fields/traction_y");
  double most = 0.0;
  for (std::size_t k = 0; k < px.size(); ++k) most = std::max(most, std::hypot(px[k], py[k]));
  EXPECT_LE(most, 250e6 * (1.0 + 1e-12));  // σ_m,T (A.3)
  EXPECT_NEAR(most, 250e6, 1e-6 * 250e6);   // and reached where it slides
}

struct BadFriction {
  std::string name, args, expected;
};
void PrintTo(const BadFriction& b, std::ostream* os) { *os << b.name; }

class FrictionCliBadInput : public ::testing::TestWithParam<BadFriction> {};

TEST_P(FrictionCliBadInput, ExitsWithStatus2AndNamesTheProblem) {
  const auto& p = GetParam();
  const auto out = work / ("bad-" + p.name);
  const auto r = run_cli(sphere + "--out '" + out.string() + "' " + p.args, work);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr(p.expected));
  EXPECT_THAT(r.err, ::testing::Not(HasSubstr("Usage:")));  // refused by the study, not by the parser
  EXPECT_FALSE(fs::exists(out / "contact.h5"));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, FrictionCliBadInput,
    ::testing::Values(
        BadFriction{"negative_mu", "--friction coulomb --mu -0.5", "contact.friction_coefficient"},
        BadFriction{"gross_sliding", "--friction coulomb --mu 0.5 --tangential-pressure 8e-5",
                    "the contact slides as a whole (gross sliding)"},
        BadFriction{"gross_sliding_names_the_key", "--friction coulomb --mu 0.5 --tangential-pressure 8e-5",
                    "key 'contact.tangential_pressure' = 8e-05"},
        BadFriction{"tresca_without_strength", "--friction tresca --tangential-pressure 4e-5",
                    "contact.shear_strength"},
        BadFriction{"unknown_law", "--friction amontons", "key 'contact.friction' = \"amontons\": not a known choice"},
        BadFriction{"negative_strength", "--friction coulomb --mu 0.5 --tensile-strength -1",
                    "contact.tensile_strength"},
        BadFriction{"interference", "--friction coulomb --mu 0.5 --set contact.interference=1e-3",
                    "imposes the mean tractions"},
        BadFriction{"negative_depth", "--friction coulomb --mu 0.5 --set 'contact.stress_depths=[-0.1]'",
                    "contact.stress_depths"}),
    [](const auto& p) { return p.param.name; });

TEST(FrictionCli, FrictionNeedsPoissonsRatio) {
  const auto r = run_cli("contact --set contact.grid=32 --set contact.size=1 --set contact.sphere.radius=1 "
                         "--e-star 1 --pressure 0.01 --friction coulomb --mu 0.3 --out nu",
                         work);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("contact.poisson"));
}
