// `wearscale contact`: a rough or spherical surface pressed on an elastic
// flat from a case and flags; outputs for ParaView; bad input → status 2.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_contact_cli_");
const std::filesystem::path work = work_scratch.path();
const std::string rough_case = "'" + std::string(WEARSCALE_SOURCE_DIR) + "/cases/rough_contact.toml'";
}  // namespace

TEST(ContactCli, RoughCaseWritesFieldsClustersAndJson) {
  const auto r = run_cli("contact " + rough_case + " --set contact.grid=128 --out rc --json", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["results"]["mean_pressure"]["value"].get<double>(), 0.03, 1e-12);
  EXPECT_LT(j["results"]["error"]["value"].get<double>(), 1e-10);
  EXPECT_GT(j["results"]["clusters"]["value"].get<double>(), 10);
  EXPECT_EQ(j["parameters"]["contact"]["grid"], 128);
  for (const char* f : {"contact.h5", "contact.xdmf", "clusters.csv", "summary.json"})
    EXPECT_TRUE(fs::exists(work / "rc" / f)) << f;
}

TEST(ContactCli, TheTwoLevelPreconditionerGivesTheSameContact) {
  // contact.preconditioner = "two-level" (S on a 2× coarser grid): the figures of
  // the full preconditioner to the tolerance's accuracy.
  std::map<std::string, nlohmann::json> results;
  for (const std::string pre : {"full", "two-level"}) {
    const auto r = run_cli("contact " + rough_case + " --set contact.grid=128 --set contact.preconditioner=" + pre +
                               " --out pre-" + pre + " --json",
                           work);
    ASSERT_EQ(r.status, 0) << r.err;
    results[pre] = nlohmann::json::parse(r.out);
  }
  const auto& a = results["full"]["results"];
  const auto& b = results["two-level"]["results"];
  EXPECT_EQ(results["two-level"]["parameters"]["contact"]["preconditioner"], "two-level");
  EXPECT_EQ(a["contact_fraction"]["value"], b["contact_fraction"]["value"]);
  EXPECT_EQ(a["clusters"]["value"], b["clusters"]["value"]);
  EXPECT_NEAR(b["interference"]["value"].get<double>(), a["interference"]["value"].get<double>(),
              1e-8 * std::abs(a["interference"]["value"].get<double>()));
  EXPECT_LT(b["error"]["value"].get<double>(), 1e-10);
}

TEST(ContactCli, ASphereGivesTheHertzContactRadius) {
  // R = 1, E* = 1, a = 0.04 on a unit cell: F = 4E*a³/(3R).
  const double a = 0.04, load = 4.0 * a * a * a / 3.0;
  const auto r = run_cli("contact --set contact.grid=512 --set contact.size=1 --set contact.sphere.radius=1 "
                         "--e-star 1 --load " + std::to_string(load) + " --out sphere --json", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const double fraction = nlohmann::json::parse(r.out)["results"]["contact_fraction"]["value"].get<double>();
  EXPECT_NEAR(std::sqrt(fraction / std::numbers::pi), a, 0.02 * a);
  EXPECT_EQ(nlohmann::json::parse(r.out)["results"]["clusters"]["value"], 1);
}

TEST(ContactCli, AFreeBoundaryGivesTheHertzApproachWithoutImages) {
  // R = 1, E* = 1, a = 0.04 (64 cells across) on a window of 4 contact diameters: δ = a²/R.
  const double a = 0.04, load = 4.0 * a * a * a / 3.0;
  const auto r = run_cli("contact --set contact.grid=256 --set contact.size=0.32 --set contact.sphere.radius=1 "
                         "--set contact.boundary=free --e-star 1 --load " + std::to_string(load) +
                         " --out free --json", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["results"]["interference"]["value"].get<double>(), a * a, 0.01 * a * a);
  EXPECT_EQ(j["parameters"]["contact"]["boundary"], "free");
}

TEST(ContactCli, AFreeWindowSmallerThanItsContactIsRefused) {
  const double a = 0.04, load = 4.0 * a * a * a / 3.0;
  const auto out = work / "free-small";
  const auto r = run_cli("contact --set contact.grid=32 --set contact.size=0.05 --set contact.sphere.radius=1 "
                         "--set contact.boundary=free --e-star 1 --load " + std::to_string(load) + " --out '" +
                         out.string() + "'", work);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("edge"));
  EXPECT_FALSE(fs::exists(out / "contact.h5"));
}

struct BadContact {
  std::string name, args, expected;
};
void PrintTo(const BadContact& b, std::ostream* os) { *os << b.name; }

class ContactCliBadInput : public ::testing::TestWithParam<BadContact> {};

TEST_P(ContactCliBadInput, ExitsWithStatus2AndNamesTheProblem) {
  const auto& p = GetParam();
  const auto out = work / ("bad-" + p.name);
  const auto r = run_cli("contact " + rough_case + " --set contact.grid=128 --out '" + out.string() + "' " + p.args, work);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr(p.expected));
  EXPECT_FALSE(fs::exists(out / "contact.h5"));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ContactCliBadInput,
    ::testing::Values(
        BadContact{"negative_modulus", "--e-star -1", "contact.e_star"},
        BadContact{"ks_above_nyquist", "--set contact.rough.k_s=80", "contact.rough.k_s"},
        BadContact{"hurst_zero", "--set contact.rough.hurst=0", "contact.rough.hurst"},
        BadContact{"two_loads", "--load 1", "exactly one of mean_pressure, normal_load, interference"},
        BadContact{"negative_pressure", "--pressure -1", "contact.mean_pressure"},
        BadContact{"typo", "--set contact.tolerence=1e-8", "did you mean 'tolerance'"},
        BadContact{"missing_file", "--surface /nonexistent.h5", "/nonexistent.h5"},
        BadContact{"unknown_boundary", "--set contact.boundary=fixed", "contact.boundary"},
        BadContact{"unknown_preconditioner", "--set contact.preconditioner=multigrid", "contact.preconditioner"},
        BadContact{"free_with_friction", "--set contact.boundary=free --set contact.friction=coulomb "
                   "--set contact.poisson=0.3 --set contact.friction_coefficient=0.5", "frictionless contact only"}),
    [](const auto& p) { return p.param.name; });

TEST(ContactCli, PoissonRatioAboveOneHalfIsRefused) {
  const auto r = run_cli("contact --set contact.grid=32 --set contact.size=1 --set contact.sphere.radius=1 "
                         "--set contact.young=1 --set contact.poisson=0.6 --pressure 0.01 --out nu",
                         work);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("contact.poisson"));
  EXPECT_THAT(r.err, HasSubstr("(-1, 0.5]"));
}
