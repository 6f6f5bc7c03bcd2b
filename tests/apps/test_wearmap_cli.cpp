// `wearscale wearmap analytic2d|analytic3d`: the analytic wear maps of thesis
// Fig. 3.7 and Fig. 4.6 as HDF5 (+ XDMF sidecar) + CSV (+ PNG), from flags or
// a case file ([wearmap.analytic2d|3d], flags override it, --set overrides
// both); bad flags or keys → status 2 naming them, nothing written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "xdmf_check.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_wearmap_cli_");
const std::filesystem::path work = work_scratch.path();

// Rows of the map CSV (after the '#' comments and the header): x, y, region, then the layers.
std::vector<std::vector<double>> read_rows(const fs::path& csv, std::string& header) {
  std::ifstream in(csv);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (header.empty()) {
      header = line;
      continue;
    }
    std::vector<double> row;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}
}  // namespace

TEST(WearmapCli, Analytic3dWritesTheMapOfFigure46AtMostInteraction) {
  const auto r = run_cli("wearmap analytic3d --interaction max --n 41 --out m3 --json", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["results"]["C_inter"]["value"].get<double>(), 2.0 / 3.0, 1e-15);
  // Adjacent contacts (d = l) detach one particle from d = d*/(1 + π/4) (4.48).
  EXPECT_NEAR(j["results"]["least_d_one_separated"]["value"].get<double>(),
              1.0 / (1.0 + std::numbers::pi / 4), 1e-12);
  for (const char* f : {"wearmap_analytic3d.h5", "wearmap_analytic3d.csv"}) EXPECT_TRUE(fs::exists(work / "m3" / f)) << f;
  if (std::system("command -v gnuplot >/dev/null 2>&1") == 0) {
    ASSERT_TRUE(fs::exists(work / "m3" / "wearmap_analytic3d.png"));
    EXPECT_GT(fs::file_size(work / "m3" / "wearmap_analytic3d.png"), 10000u);
  }

  // Every CSV row sits on the right side of the lines R = 1 of (4.48), and its R columns are (4.48).
  std::string header;
  const auto rows = read_rows(work / "m3" / "wearmap_analytic3d.csv", header);
  EXPECT_EQ(header, "d_over_l,dstar_over_l,region,R_one_separated,R_two_separated,R_combined");
  ASSERT_EQ(rows.size(), 41u * 41u);
  const double a = 3.0 * std::numbers::pi / 8.0 * 2.0 / 3.0;
  for (const auto& row : rows) {
    const double x = row[0], y = row[1];
    const double r1 = (1 + a * x) * x / y, r2 = (2 + a * x) * x / y / 2, rc = (2 + a * x) * x / y * x * x / ((1 + x) * (1 + x));
    EXPECT_NEAR(row[3], r1, 1e-8 * r1);  // the CSV keeps 10 digits of x, y and R
    EXPECT_NEAR(row[4], r2, 1e-8 * r2);
    EXPECT_NEAR(row[5], rc, 1e-8 * rc);
    EXPECT_EQ(row[2], rc >= 1 ? 3 : r2 >= 1 ? 2 : r1 >= 1 ? 1 : 0) << x << " " << y;
  }

  // The HDF5 file holds the same map.
  wearscale::H5Reader h5(work / "m3" / "wearmap_analytic3d.h5");
  EXPECT_EQ(h5.read_series("/axes/d_over_l").size(), 41u);
  EXPECT_EQ(h5.shape("/region"), (std::vector<std::size_t>{41, 41}));
  const auto region = h5.read_field("/region");
  for (std::size_t k = 0; k < rows.size(); ++k) ASSERT_EQ(region[k], rows[k][2]) << k;
  EXPECT_NEAR(h5.number_attribute("/", "C_inter"), 2.0 / 3.0, 1e-15);
}

TEST(WearmapCli, Analytic3dTakesPoissonRatioAndAngle) {
  const auto r = run_cli("wearmap analytic3d --nu 0.3 --theta 1.5707963267948966 --n 8 --out m3nu --json", work);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(nlohmann::json::parse(r.out)["results"]["C_inter"]["value"].get<double>(), 0.7 / 1.7, 1e-12);  // (4.49)
}

TEST(WearmapCli, Analytic2dWritesTheMapOfFigure37) {
  const auto r = run_cli("wearmap analytic2d --dr-over-dstar 0:4 --da-over-dstar 0:10 --n 40 --out m2", work);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("fraction_combined"));
  std::string header;
  const auto rows = read_rows(work / "m2" / "wearmap_analytic2d.csv", header);
  EXPECT_EQ(header, "dr_over_dstar,da_over_dstar,region,R_sep,R_comb,kappa,kappa_min");
  ASSERT_EQ(rows.size(), 1600u);  // 40 × 40 centres: none on a line (d_r = (2k+1)/20, d_a = (2j+1)/8)
  for (const auto& row : rows) {
    const double dr = row[0], da = row[1];
    EXPECT_EQ(row[2], da < dr ? -1 : dr < 1 ? 0 : da <= dr * dr ? 2 : 1) << dr << " " << da;  // (3.25), (3.27)
  }
  EXPECT_TRUE(fs::exists(work / "m2" / "wearmap_analytic2d.h5"));
}

struct BadWearmap {
  std::string name, args, expected;
};
void PrintTo(const BadWearmap& b, std::ostream* os) { *os << b.name; }

class WearmapCliBadInput : public ::testing::TestWithParam<BadWearmap> {};

TEST_P(WearmapCliBadInput, ExitsWithStatus2AndNamesTheFlag) {
  const auto& p = GetParam();
  const auto out = work / ("bad-" + p.name);
  const auto r = run_cli("wearmap " + p.args + " --out '" + out.string() + "'", work);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr(p.expected));
  EXPECT_FALSE(fs::exists(out / "wearmap_analytic3d.h5"));
  EXPECT_FALSE(fs::exists(out / "wearmap_analytic2d.h5"));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, WearmapCliBadInput,
    ::testing::Values(
        BadWearmap{"overlapping_contacts", "analytic3d --d-over-l 0:1.5",
                   "--d-over-l 0:1.5: key 'wearmap.analytic3d.d_over_l[1]' = 1.5: out of range; allowed: [0, 1]"},
        BadWearmap{"reversed_range", "analytic3d --dstar-over-l 2:1",
                   "--dstar-over-l 2:1: key 'wearmap.analytic3d.dstar_over_l' = [ 2, 1 ]: not a range"},
        BadWearmap{"not_a_range", "analytic2d --dr-over-dstar 3", "--dr-over-dstar = '3' is not a range"},
        BadWearmap{"negative_size", "analytic2d --da-over-dstar -1:2",
                   "key 'wearmap.analytic2d.da_over_dstar[0]' = -1: out of range; allowed: ≥ 0"},
        BadWearmap{"poisson", "analytic3d --nu 0.7",
                   "--nu 0.7: key 'wearmap.analytic3d.nu' = 0.7: out of range; allowed: (-1, 0.5]"},
        BadWearmap{"interaction", "analytic3d --interaction medium", "--interaction"},
        BadWearmap{"interaction_and_nu", "analytic3d --interaction max --nu 0.3", "excludes"},
        BadWearmap{"too_many_points", "analytic2d --n 5000", "--n"},
        BadWearmap{"no_kind", "", "wearmap"}),
    [](const auto& p) { return p.param.name; });

TEST(WearmapCli, AnOutputFolderThatIsAFileIsBadInput) {
  const auto r = run_cli("wearmap analytic2d --n 4 --out /dev/null", work);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("--out = '/dev/null'"));
}

// ------------------------------------------------------------ case files ---

namespace {
void write_text(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}
}  // namespace

TEST(WearmapCli, CaseFileGivesTheSameMapAsTheFlags) {
  // A map off the defaults (ν = 0.3, θ = 1 rad, both ranges narrowed) from the flags and from a case file.
  const auto flags = run_cli("wearmap analytic3d --nu 0.3 --theta 1 --d-over-l 0.2:0.9 --dstar-over-l 0.1:1.5 "
                             "--n 17 --out by-flags --json", work);
  ASSERT_EQ(flags.status, 0) << flags.err;
  write_text(work / "a3.toml", "[wearmap.analytic3d]\nnu = 0.3\ntheta = 1.0\nd_over_l = [0.2, 0.9]\n"
                               "dstar_over_l = [0.1, 1.5]\nn = 17\n[output]\ndir = \"by-case\"\n");
  const auto file = run_cli("wearmap analytic3d a3.toml --json", work);
  ASSERT_EQ(file.status, 0) << file.err;
  const auto jf = nlohmann::json::parse(flags.out), jc = nlohmann::json::parse(file.out);
  EXPECT_EQ(jc["output_dir"], "by-case");
  EXPECT_EQ(jf["results"], jc["results"]);  // same numbers to the last bit
  EXPECT_NEAR(jc["results"]["C_inter"]["value"].get<double>(), (1 - 0.3 * std::pow(std::sin(1.0), 2)) / 1.7, 1e-15);
  EXPECT_EQ(slurp(work / "by-flags" / "wearmap_analytic3d.csv"), slurp(work / "by-case" / "wearmap_analytic3d.csv"));
  // The resolved parameters (defaults included) in the summary and the HDF5 file.
  const auto& p = jc["parameters"]["wearmap"]["analytic3d"];
  EXPECT_EQ(p["n"], 17);
  EXPECT_EQ(p["d_over_l"], nlohmann::json::parse("[0.2, 0.9]"));
  EXPECT_EQ(jf["parameters"]["wearmap"]["analytic3d"], p);
  EXPECT_EQ(nlohmann::json::parse(slurp(work / "by-case" / "summary.json"))["parameters"],
            jc["parameters"]);
  const wearscale::H5Reader h5(work / "by-case" / "wearmap_analytic3d.h5");
  const auto toml = h5.string_attribute("/", "case_toml");
  EXPECT_THAT(toml, HasSubstr("[wearmap.analytic3d]"));
  EXPECT_THAT(toml, HasSubstr("n = 17"));
  EXPECT_THAT(toml, HasSubstr("theta = 1"));
  EXPECT_THAT(toml, HasSubstr("dir = 'by-case'"));
}

TEST(WearmapCli, FlagsOverrideTheFileAndSetOverridesBoth) {
  write_text(work / "a2.toml", "[wearmap.analytic2d]\nn = 8\ndr_over_dstar = [0.0, 4.0]\n");
  auto rows_of = [&](const std::string& args, const std::string& out) {
    const auto r = run_cli("wearmap analytic2d a2.toml " + args + " --out " + out, work);
    EXPECT_EQ(r.status, 0) << r.err;
    std::string header;
    return read_rows(work / out / "wearmap_analytic2d.csv", header);
  };
  const auto file = rows_of("", "o-file");
  ASSERT_EQ(file.size(), 64u);
  EXPECT_DOUBLE_EQ(file.back()[0], 3.75);  // the last d_r/d* cell centre of [0, 4] in 8 cells
  const auto flag = rows_of("--n 6", "o-flag");
  ASSERT_EQ(flag.size(), 36u);
  EXPECT_NEAR(flag.back()[0], 4.0 - 4.0 / 12, 1e-9);  // the file's range kept (the CSV keeps 10 digits)
  const auto set = rows_of("--n 6 --set wearmap.analytic2d.n=5 --dr-over-dstar 0:2", "o-set");
  ASSERT_EQ(set.size(), 25u);
  EXPECT_NEAR(set.back()[0], 1.8, 1e-9);
}

struct BadWearmapCase {
  std::string name, kind, toml, expected;
};
void PrintTo(const BadWearmapCase& b, std::ostream* os) { *os << b.name; }

class WearmapCliBadCase : public ::testing::TestWithParam<BadWearmapCase> {};

TEST_P(WearmapCliBadCase, ExitsWithStatus2NamingFileKeyValueAndRangeAndWritesNothing) {
  const auto& p = GetParam();
  const auto out = work / ("badcase-" + p.name);
  const auto file = work / ("bad-" + p.name + ".toml");
  write_text(file, p.toml + "\n[output]\ndir = '" + out.string() + "'\n");
  const auto r = run_cli("wearmap " + p.kind + " '" + file.string() + "'", work);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr(file.string() + ":")) << "names the file";
  EXPECT_THAT(r.err, HasSubstr(p.expected));
  EXPECT_FALSE(fs::exists(out)) << "no output folder";
}

INSTANTIATE_TEST_SUITE_P(
    Cases, WearmapCliBadCase,
    ::testing::Values(
        BadWearmapCase{"poisson", "analytic3d", "[wearmap.analytic3d]\nnu = 0.7",
                ":2: key 'wearmap.analytic3d.nu' = 0.7: out of range; allowed: (-1, 0.5]"},
        BadWearmapCase{"overlapping_contacts", "analytic3d", "[wearmap.analytic3d]\nd_over_l = [0.0, 1.5]",
                "key 'wearmap.analytic3d.d_over_l[1]' = 1.5: out of range; allowed: [0, 1]"},
        BadWearmapCase{"reversed_range", "analytic3d", "[wearmap.analytic3d]\ndstar_over_l = [2.0, 1.0]",
                "key 'wearmap.analytic3d.dstar_over_l' = [ 2.0, 1.0 ]: not a range [MIN, MAX] with MIN < MAX; "
                "allowed: [MIN, MAX] of d*/l with MIN < MAX, each ≥ 0"},
        BadWearmapCase{"not_a_range", "analytic2d", "[wearmap.analytic2d]\ndr_over_dstar = 3.0",
                "key 'wearmap.analytic2d.dr_over_dstar' = 3: expected an array, got a float"},
        BadWearmapCase{"too_many_points", "analytic2d", "[wearmap.analytic2d]\nn = 5000",
                ":2: key 'wearmap.analytic2d.n' = 5000: out of range; allowed: integer [2, 4096]"},
        BadWearmapCase{"interaction", "analytic3d", "[wearmap.analytic3d]\ninteraction = 'medium'",
                "key 'wearmap.analytic3d.interaction' = \"medium\": not a known choice; allowed: \"max\", \"min\""},
        BadWearmapCase{"interaction_and_nu", "analytic3d", "[wearmap.analytic3d]\ninteraction = 'max'\nnu = 0.3",
                "key 'wearmap.analytic3d.nu' = 0.3: cannot be set together with interaction"},
        BadWearmapCase{"misspelt_key", "analytic3d", "[wearmap.analytic3d]\nthetta = 1.0",
                "key 'wearmap.analytic3d.thetta' = 1: unknown key (no component of this case reads it); allowed: "
                "keys read in [wearmap.analytic3d]: d_over_l, dstar_over_l, interaction, n, nu, theta "
                "(did you mean 'theta'?)"},
        BadWearmapCase{"other_kind_table", "analytic2d", "[wearmap.analytic3d]\nn = 10", "key 'wearmap.analytic3d"}),
    [](const auto& p) { return p.param.name; });

TEST(WearmapCli, SidecarsLetParaViewOpenTheMapFields) {
  for (const std::string kind : {"analytic2d", "analytic3d"}) {
    const auto out = "xdmf-" + kind;
    const auto r = run_cli("wearmap " + kind + " --n 12 --out " + out + " --json", work);
    ASSERT_EQ(r.status, 0) << r.err;
    const fs::path xmf = work / out / ("wearmap_" + kind + ".xdmf"), h5 = work / out / ("wearmap_" + kind + ".h5");
    const auto files = nlohmann::json::parse(r.out)["files"];
    EXPECT_NE(std::find(files.begin(), files.end(), (fs::path(out) / xmf.filename()).string()), files.end());
    const std::vector<std::string> layers =
        kind == "analytic2d"
            ? std::vector<std::string>{"/region", "/ratio/R_sep", "/ratio/R_comb", "/ratio/kappa", "/ratio/kappa_min"}
            : std::vector<std::string>{"/region", "/ratio/R_one_separated", "/ratio/R_two_separated",
                                       "/ratio/R_combined"};
    expect_xdmf_describes(xmf, h5, {12, 12}, layers);
  }
}

// The three kinds, run one after the other without --out (as the README runs
// them), each into a folder of its own: no map replaces another's.
TEST(WearmapCli, EachKindHasItsOwnDefaultFolderSoNoneReplacesAnother) {
  const fs::path dir = work / "defaults";
  fs::create_directories(dir);
  for (const std::string& cmd :
       {"wearmap analytic2d --n 11 -q", "wearmap analytic3d --n 11 -q",
        "wearmap rough --n 32 --ql 2 --seeds 1 --n-loads 2 --n-dstar 2 -q"}) {
    const auto r = run_cli(cmd, dir);
    ASSERT_EQ(r.status, 0) << cmd << ": " << r.err;
  }
  for (const char* kind : {"analytic2d", "analytic3d", "rough"}) {
    const fs::path folder = dir / "out" / ("wearmap-" + std::string(kind));
    EXPECT_TRUE(fs::exists(folder / ("wearmap_" + std::string(kind) + ".h5"))) << folder;
    EXPECT_TRUE(fs::exists(folder / ("wearmap_" + std::string(kind) + ".csv"))) << folder;
    EXPECT_TRUE(fs::exists(folder / "summary.json")) << folder;
  }
  EXPECT_FALSE(fs::exists(dir / "out" / "wearmap"));
}
