// `wearscale wearmap rough`: the numerical wear map of rough contacts (ch. 5)
// on a small grid: its files, the three regimes along the load at one d*,
// the naive baseline agreeing with the fast model (the whole map), the case file
// ([wearmap.rough]) giving the same map as the flags, the XDMF sidecar, and
// bad flags or keys → status 2 naming them, with nothing written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "xdmf_check.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_wearmap_rough_cli_");
const std::filesystem::path work = work_scratch.path();
}  // namespace

TEST(WearmapRoughCli, SmallMapWritesFilesAndShowsTheRegimes) {
  const auto r = run_cli("wearmap rough --n 64 --ql 4 --qs 8 --seeds 2 --loads 0.005:0.2 --n-loads 5 "
                         "--dstar-over-l 0.05:0.2 --n-dstar 3 --naive-pixels 2 --out small --json", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* f : {"wearmap_rough.h5", "wearmap_rough.xdmf", "wearmap_rough.csv", "wearmap_rough_particles.csv",
                        "wearmap_rough_curves.csv", "wearmap_rough_peaks.csv", "summary.json"})
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
  // Fig. 5.7's maxima are read off the smoothed curves (§5.2; 5 loads: the
  // filter shrinks to 5 points, degree 3): each lies among the valid pixels of
  // its d*, and the largest is reported.
  std::ifstream peaks(work / "small" / "wearmap_rough_peaks.csv");
  double largest = 0.0;
  std::size_t found = 0;
  while (std::getline(peaks, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'd') continue;
    std::vector<double> row;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) row.push_back(std::stod(cell));
    ASSERT_EQ(row.size(), 5u);
    if (row[4] == 0.0) continue;
    ++found;
    largest = std::max(largest, row[2]);
    bool at_a_valid_pixel = false;
    for (const auto& px : rows)
      if (std::abs(px[0] - row[1]) < 1e-9 && std::abs(px[1] - row[0]) < 1e-9 * row[0]) at_a_valid_pixel = px[8] == 1.0;
    EXPECT_TRUE(at_a_valid_pixel) << line;
  }
  EXPECT_GT(found, 0u);
  EXPECT_NEAR(j["results"]["max_count_smoothed"]["value"].get<double>(), largest, 1e-8 * largest);  // CSV: 10 digits
}

// The naive baseline (one full solve per candidate) and the fast evaluator
// make the same map: every pixel's particle count, volume, largest particle
// and validity, and every particle, to the last printed digit — on a map that
// holds the three regimes (no particle, particles, invalid pixels).
TEST(WearmapRoughCli, TheNaiveMapIsTheFastMap) {
  const std::string map = "wearmap rough --n 64 --ql 4 --qs 16 --seeds 2 --loads 0.005:0.3 --n-loads 6 "
                          "--dstar-over-l 0.02:0.2 --n-dstar 4 -q --json ";
  const auto fast = run_cli(map + "--out same-fast", work);
  const auto naive = run_cli(map + "--naive --out same-naive", work);
  ASSERT_EQ(fast.status, 0) << fast.err;
  ASSERT_EQ(naive.status, 0) << naive.err;
  const auto text = [](const fs::path& f) {
    std::ifstream in(f);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  for (const char* f : {"wearmap_rough.csv", "wearmap_rough_particles.csv"})
    EXPECT_EQ(text(work / "same-fast" / f), text(work / "same-naive" / f)) << f;
  // The naive run did evaluate in full what the fast one rejects by its bound.
  const auto evaluations = [](const std::string& out) {
    return nlohmann::json::parse(out)["results"]["energy_evaluations"]["value"].get<double>();
  };
  EXPECT_GT(evaluations(naive.out), 2.0 * evaluations(fast.out));
  // The map holds every regime: pixels without particles, valid pixels with some, invalid ones.
  const auto csv = text(work / "same-fast" / "wearmap_rough.csv");
  std::size_t none = 0, some = 0, invalid = 0;
  std::stringstream rows(csv);
  for (std::string line; std::getline(rows, line);) {
    if (line.empty() || line[0] == '#' || line[0] == 'p') continue;
    std::vector<double> row;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) row.push_back(std::stod(cell));
    if (row[8] == 0.0) ++invalid;
    else if (row[2] == 0.0) ++none;
    else ++some;
  }
  EXPECT_GT(none, 0u);
  EXPECT_GT(some, 0u);
  EXPECT_GT(invalid, 0u);
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
    ::testing::Values(BadRough{"loads", "--loads 0.3:0.1", "--loads 0.3:0.1: key 'wearmap.rough.loads' = ["},
                      BadRough{"loads_text", "--loads abc", "--loads = 'abc'"},
                      BadRough{"load_one", "--loads 0.5:1.5",
                               "--loads 0.5:1.5: key 'wearmap.rough.loads[1]' = 1.5: out of range; allowed: (0, 1)"},
                      BadRough{"dstar", "--dstar-over-l 0:0.1",
                               "--dstar-over-l 0:0.1: key 'wearmap.rough.dstar_over_l[0]' = 0: out of range; "
                               "allowed: > 0"},
                      BadRough{"hurst", "--hurst 1.5",
                               "--hurst 1.5: key 'wearmap.rough.hurst' = 1.5: out of range; allowed: (0, 1]"},
                      BadRough{"qs", "--qs 40",
                               "--qs 40: key 'wearmap.rough.q_s' = 40: not allowed with q_l = 2, q_s = 40 and n = 32; "
                               "allowed: 1 ≤ q_l ≤ q_s ≤ n/2 = 16"},
                      BadRough{"nu", "--nu 0.7", "--nu 0.7: key 'wearmap.rough.nu' = 0.7: out of range; allowed: (-1, 0.5]"},
                      BadRough{"sigma_m", "--tensile-strength -1",
                               "--tensile-strength -1: key 'wearmap.rough.tensile_strength' = -1: out of range; "
                               "allowed: > 0"},
                      BadRough{"spot", "--spot 2", "--spot 2: key 'wearmap.rough.spot' = 2: out of range; allowed: [0, 1]"},
                      BadRough{"set_overrides_flag", "--hurst 0.5 --set wearmap.rough.hurst=0",
                               "--set wearmap.rough.hurst=0: key 'wearmap.rough.hurst' = 0: out of range"}),
    [](const ::testing::TestParamInfo<BadRough>& p) { return p.param.name; });

// ------------------------------------------------------------ case files ---

namespace {
void write_text(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}
// The results that do not depend on the clock.
nlohmann::json timeless(nlohmann::json results) {
  for (const char* k : {"seconds", "seconds_per_pixel", "contact_seconds", "model_setup_seconds", "detach_seconds"})
    results.erase(k);
  return results;
}
const char* small_case = "[wearmap.rough]\nn = 32\nq_l = 2\nseeds = 1\nloads = [0.02, 0.2]\nn_loads = 3\n"
                         "dstar_over_l = [0.05, 0.2]\nn_dstar = 2\nspot = 0.1\n";
}  // namespace

TEST(WearmapRoughCli, CaseFileGivesTheSameMapAsTheFlagsAndRecordsIt) {
  const auto flags = run_cli("wearmap rough --n 32 --ql 2 --seeds 1 --loads 0.02:0.2 --n-loads 3 --dstar-over-l "
                             "0.05:0.2 --n-dstar 2 --spot 0.1 --out by-flags --json", work);
  ASSERT_EQ(flags.status, 0) << flags.err;
  write_text(work / "rough.toml", std::string(small_case) + "[output]\ndir = \"by-case\"\n");
  const auto file = run_cli("wearmap rough rough.toml --json", work);
  ASSERT_EQ(file.status, 0) << file.err;
  const auto jf = nlohmann::json::parse(flags.out), jc = nlohmann::json::parse(file.out);
  EXPECT_EQ(jc["output_dir"], "by-case");
  EXPECT_EQ(timeless(jf["results"]), timeless(jc["results"]));
  EXPECT_EQ(jc["results"]["pixels"]["value"].get<double>(), 6.0);
  EXPECT_EQ(slurp(work / "by-flags" / "wearmap_rough.csv"), slurp(work / "by-case" / "wearmap_rough.csv"));
  EXPECT_EQ(slurp(work / "by-flags" / "wearmap_rough_particles.csv"),
            slurp(work / "by-case" / "wearmap_rough_particles.csv"));
  // Resolved parameters, defaults included (q_s = n/8, H = 0.8, ν = 0.3), in the summary and the HDF5 file.
  const auto& p = jc["parameters"]["wearmap"]["rough"];
  EXPECT_EQ(p, jf["parameters"]["wearmap"]["rough"]);
  EXPECT_EQ(p["q_s"].get<double>(), 4.0);
  EXPECT_EQ(p["hurst"].get<double>(), 0.8);
  EXPECT_EQ(p["nu"].get<double>(), 0.3);
  EXPECT_EQ(p["energy_balance"], "cumulative");
  ASSERT_EQ(jc["axes"]["p_N_tilde"].size(), 3u);
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_NEAR(jc["axes"]["p_N_tilde"][k].get<double>(), 0.02 + 0.09 * double(k), 1e-15);
  const wearscale::H5Reader h5(work / "by-case" / "wearmap_rough.h5");
  const auto toml = h5.string_attribute("/", "case_toml");
  EXPECT_THAT(toml, HasSubstr("[wearmap.rough]"));
  EXPECT_THAT(toml, HasSubstr("n_loads = 3"));
  EXPECT_THAT(toml, HasSubstr("q_s = 4"));
}

TEST(WearmapRoughCli, FlagsOverrideTheFileAndSetOverridesBoth) {
  write_text(work / "rough2.toml", small_case);
  auto pixels = [&](const std::string& args) {
    const auto r = run_cli("wearmap rough rough2.toml --json --out o " + args, work);
    EXPECT_EQ(r.status, 0) << r.err;
    return r.status == 0 ? nlohmann::json::parse(r.out)["results"]["pixels"]["value"].get<double>() : -1.0;
  };
  EXPECT_EQ(pixels("--n-loads 2"), 4.0);                                 // 2 × 2, the file's n_dstar
  EXPECT_EQ(pixels("--n-loads 2 --set wearmap.rough.n_loads=1"), 2.0);  // 1 × 2
}

struct BadRoughCase {
  std::string name, toml, expected;
};
void PrintTo(const BadRoughCase& b, std::ostream* os) { *os << b.name; }

class WearmapRoughCliBadCase : public ::testing::TestWithParam<BadRoughCase> {};

TEST_P(WearmapRoughCliBadCase, ExitsWithStatus2NamingFileKeyValueAndRangeAndWritesNothing) {
  const auto& p = GetParam();
  const auto out = work / ("badcase-" + p.name);
  const auto file = work / ("bad-" + p.name + ".toml");
  write_text(file, "[wearmap.rough]\nn = 32\nq_l = 2\nseeds = 1\nn_loads = 2\nn_dstar = 2\n" + p.toml +
                       "\n[output]\ndir = '" + out.string() + "'\n");
  const auto r = run_cli("wearmap rough '" + file.string() + "'", work);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr(file.string() + ":7: key")) << "names the file and line";
  EXPECT_THAT(r.err, HasSubstr(p.expected));
  EXPECT_FALSE(fs::exists(out)) << "no output folder";
}

INSTANTIATE_TEST_SUITE_P(
    Cases, WearmapRoughCliBadCase,
    ::testing::Values(
        BadRoughCase{"hurst", "hurst = 1.5", "key 'wearmap.rough.hurst' = 1.5: out of range; allowed: (0, 1]"},
        BadRoughCase{"load_one", "loads = [0.5, 1.5]",
                     "key 'wearmap.rough.loads[1]' = 1.5: out of range; allowed: (0, 1)"},
        BadRoughCase{"reversed_loads", "loads = [0.5, 0.25]",
                     "key 'wearmap.rough.loads' = [ 0.5, 0.25 ]: not a range [MIN, MAX] with MIN < MAX"},
        BadRoughCase{"naive_pixels", "naive_pixels = 2000",
                     "key 'wearmap.rough.naive_pixels' = 2000: out of range; allowed: integer [0, 1000]"},
        BadRoughCase{"qs", "q_s = 40", "key 'wearmap.rough.q_s' = 40: not allowed with q_l = 2, q_s = 40 and n = 32; "
                                       "allowed: 1 ≤ q_l ≤ q_s ≤ n/2 = 16"},
        BadRoughCase{"balance", "energy_balance = 'each'",
                     "key 'wearmap.rough.energy_balance' = \"each\": not a known choice; allowed: \"cumulative\", "
                     "\"per_particle\""},
        BadRoughCase{"misspelt_key", "hurts = 0.8", "key 'wearmap.rough.hurts' = 0.8: unknown key (no component of "
                                                    "this case reads it); allowed: keys read in [wearmap.rough]"},
        BadRoughCase{"misspelt_key_suggestion", "tensile_strenght = 2", "(did you mean 'tensile_strength'?)"}),
    [](const auto& p) { return p.param.name; });

TEST(WearmapRoughCli, SidecarLetsParaViewOpenTheMaps) {
  const auto r = run_cli("wearmap rough --n 32 --ql 2 --seeds 1 --n-loads 3 --n-dstar 2 --out xdmf --json", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto files = nlohmann::json::parse(r.out)["files"];
  EXPECT_NE(std::find(files.begin(), files.end(), "xdmf/wearmap_rough.xdmf"), files.end());
  // Rows p̃_N (3), columns d*/L (2), as in /maps of the HDF5 file.
  expect_xdmf_describes(work / "xdmf" / "wearmap_rough.xdmf", work / "xdmf" / "wearmap_rough.h5", {3, 2},
                        {"/maps/count_mean", "/maps/count_sd", "/maps/volume_mean", "/maps/volume_sd", "/maps/valid"});
}
