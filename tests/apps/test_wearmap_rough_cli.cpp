// `wearscale wearmap rough`: the numerical wear map of rough contacts (ch. 5)
// on a small grid: its files, the three regimes along the load at one d*,
// the naive baseline agreeing with the fast model, and bad input → status 2
// with nothing written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const fs::path work = fs::temp_directory_path() / ("wearscale_wearmap_rough_cli_" + std::to_string(::getpid()));
}  // namespace

TEST(WearmapRoughCli, SmallMapWritesFilesAndShowsTheRegimes) {
  const auto r = run_cli("wearmap rough --n 64 --ql 4 --qs 8 --seeds 2 --loads 0.005:0.2 --n-loads 5 "
                         "--dstar-over-l 0.05:0.2 --n-dstar 3 --naive-pixels 2 --out small --json", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* f : {"wearmap_rough.h5", "wearmap_rough.csv", "wearmap_rough_particles.csv",
                        "wearmap_rough_curves.csv", "wearmap_rough_summary.json"})
    EXPECT_TRUE(fs::exists(work / "small" / f)) << f;
  EXPECT_EQ(j["results"]["pixels"]["value"].get<double>(), 15.0);
  // The naive baseline (one full solve per candidate) finds the same particles as the fast evaluator.
  EXPECT_TRUE(j["baseline"]["same_particle_counts"].get<bool>());
  EXPECT_GT(j["baseline"]["naive_solves"].get<double>(), 0.0);
  // Per-pixel CSV: 15 rows; at the lightest load and the largest d*, no particle (plastic).
  std::ifstream csv(work / "small" / "wearmap_rough.csv");
  std::string line;
  std::vector<std::vector<double>> rows;
  while (std::getline(csv, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'p') continue;
    std::vector<double> row;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  ASSERT_EQ(rows.size(), 15u);
  EXPECT_EQ(rows[2][2], 0.0);  // p̃_N = 0.005, d*/L = 0.2: count_mean
  // Wear volume grows with the load at every d* (column 4 = volume_mean; rows are load-major).
  for (std::size_t d = 0; d < 3; ++d)
    for (std::size_t l = 1; l < 5; ++l) EXPECT_GE(rows[l * 3 + d][4], rows[(l - 1) * 3 + d][4]) << l << "," << d;
}

struct BadRough {
  std::string name, args, expected;
};
void PrintTo(const BadRough& b, std::ostream* os) { *os << b.name; }

class WearmapRoughCliBadInput : public ::testing::TestWithParam<BadRough> {};

TEST_P(WearmapRoughCliBadInput, ExitsWithStatus2AndNamesTheProblem) {
  const auto& p = GetParam();
  const auto out = work / ("bad-" + p.name);
  const auto r = run_cli("wearmap rough --n 32 --ql 2 --seeds 1 --n-loads 2 --n-dstar 2 --out '" + out.string() + "' " +
                         p.args, work);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr(p.expected));
  EXPECT_FALSE(fs::exists(out / "wearmap_rough.h5"));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, WearmapRoughCliBadInput,
    ::testing::Values(BadRough{"loads", "--loads 0.3:0.1", "--loads = '0.3:0.1'"},
                      BadRough{"loads_text", "--loads abc", "--loads = 'abc'"},
                      BadRough{"load_one", "--loads 0.5:1.5", "p̃_N = 1.5"},
                      BadRough{"dstar", "--dstar-over-l 0:0.1", "--dstar-over-l = '0:0.1'"},
                      BadRough{"hurst", "--hurst 1.5", "Hurst exponent H = 1.5"},
                      BadRough{"qs", "--qs 40",
                               "q_l = 2, q_s = 40 (in 2π/L) are not allowed; allowed: 1 ≤ q_l ≤ q_s ≤ n/2 = 16"},
                      BadRough{"nu", "--nu 0.7", "ν = 0.7"},
                      BadRough{"sigma_m", "--tensile-strength -1", "σ_m/σ_j = -1"},
                      BadRough{"spot", "--spot 2", "spot = 2"}),
    [](const auto& info) { return info.param.name; });
