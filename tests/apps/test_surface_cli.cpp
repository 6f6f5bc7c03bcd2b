// `wearscale surface` as users run it: generate → analyze recovers the Hurst
// exponent (VERIFICATION.md "Rough surfaces", ±0.05), --json and the PSD table,
// help on every subcommand, exit status 2 naming the parameter on bad input.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_surface_cli_");
const std::filesystem::path work = work_scratch.path();
constexpr double side = 1e-4;  // L = 100 µm

std::string generate_args(double hurst, const std::string& out) {
  return fmt::format("surface generate --n 256 --size 1e-4 --hurst {} --kl 4 --ks 64 --seed 5 --hprime-rms 0.2 "
                     "--out {} --json", hurst, out);
}
}  // namespace

TEST(SurfaceCli, EverySubcommandHasHelp) {
  for (const std::string sub : {"surface", "surface generate", "surface analyze"}) {
    const auto r = run_cli(sub + " --help", work);
    EXPECT_EQ(r.status, 0) << sub << r.err;
    EXPECT_THAT(r.out, HasSubstr("Usage:")) << sub;
  }
  EXPECT_THAT(run_cli("surface generate --help", work).out, HasSubstr("--hprime-rms"));
  EXPECT_THAT(run_cli("surface analyze --help", work).out, HasSubstr("--no-window"));
}

TEST(SurfaceCli, GenerateThenAnalyzeRecoversTheHurstExponent) {
  for (const double hurst : {0.3, 0.8}) {
    const std::string folder = fmt::format("rough_{}", hurst), name = folder + "/surface.h5";
    const auto gen = run_cli(generate_args(hurst, folder), work);
    ASSERT_EQ(gen.status, 0) << gen.err;
    const auto g = nlohmann::json::parse(gen.out);
    EXPECT_NEAR(g["h_prime_rms"].get<double>(), 0.2, 1e-12);  // rescaled exactly
    EXPECT_TRUE(fs::exists(work / name));
    EXPECT_TRUE(fs::exists(work / folder / "surface.xdmf"));

    // Fit band q = 2π·4/L … 2π·64/L: the whole generated band (bins wholly inside [k_l, k_s]).
    const double q_l = 2.0 * std::numbers::pi * 4.0 / side, q_s = 2.0 * std::numbers::pi * 64.0 / side;
    const auto ana = run_cli(fmt::format("surface analyze {} --no-window --qmin {} --qmax {} --psd-out psd.csv --json",
                                         name, q_l, q_s),
                             work);
    ASSERT_EQ(ana.status, 0) << ana.err;
    const auto a = nlohmann::json::parse(ana.out);
    EXPECT_NEAR(a["hurst"].get<double>(), hurst, 0.05);
    EXPECT_EQ(a["fit"]["points"].get<int>(), 60);
    EXPECT_NEAR(a["h_prime_rms"].get<double>(), 0.2, 1e-12);
    EXPECT_NEAR(a["Sa"].get<double>(), g["Sa"].get<double>(), 1e-12 * g["Sa"].get<double>());
    EXPECT_THAT(slurp(work / "out" / "surface-analyze" / "psd.csv"), HasSubstr("q_rad_per_m,C_m4,count\n"));

    // Without a band the one recorded by `generate` (k_r … k_s) is used.
    const auto by_default = nlohmann::json::parse(run_cli(fmt::format("surface analyze {} --no-window --json", name), work).out);
    EXPECT_NEAR(by_default["hurst"].get<double>(), hurst, 0.05);
  }
}

TEST(SurfaceCli, AnalyzeReadsATextGridWithItsSize) {
  // h = Σ_{k=1..7} k⁻² cos(2πk x/L) µm along x on 32 × 16 points: h_RMS² = Σ k⁻⁴/2 exactly.
  std::string text = "# a measured profile\n";
  double mean_square = 0.0;
  for (int k = 1; k <= 7; ++k) mean_square += std::pow(k, -4.0) / 2.0;
  for (int i = 0; i < 32; ++i) {
    double h = 0.0;
    for (int k = 1; k <= 7; ++k) h += std::pow(k, -2.0) * std::cos(2.0 * std::numbers::pi * k * i / 32.0);
    for (int j = 0; j < 16; ++j) text += fmt::format("{}{:.17g}", j ? "," : "", 1e-6 * h);
    text += '\n';
  }
  fs::create_directories(work);
  std::ofstream(work / "grid.csv") << text;
  const auto r = run_cli("surface analyze grid.csv --size 32e-6 --no-window --json", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["h_rms"].get<double>(), 1e-6 * std::sqrt(mean_square), 1e-18);
  EXPECT_DOUBLE_EQ(j["grid"]["lx"].get<double>(), 32e-6);
  EXPECT_DOUBLE_EQ(j["grid"]["ly"].get<double>(), 16e-6);  // square pixels
}

TEST(SurfaceCli, BadInputIsExitStatus2NamingTheParameter) {
  auto bad = [](const std::string& args) { return run_cli(args, work); };
  auto r = bad("surface generate --n 64 --size 1e-4 --hurst 1.5 --kl 2 --ks 16 --h-rms 1e-6 --out x.h5");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("'hurst' = 1.5"));
  r = bad("surface generate --n 64 --size 1e-4 --hurst 0.5 --kl 2 --ks 40 --h-rms 1e-6 --out x.h5");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("'k_s' = 40"));
  EXPECT_THAT(r.err, HasSubstr("--ks"));
  r = bad("surface generate --n 64 --size 1e-4 --hurst 0.5 --kl 20 --ks 16 --h-rms 1e-6 --out x.h5");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("k_l"));
  r = bad("surface generate --n 64 --size 1e-4 --hurst 0.5 --kl 2 --ks 16 --out x.h5");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("--hprime-rms, --h-rms, --sa"));
  r = bad("surface generate --n 64 --size 3kg --hurst 0.5 --kl 2 --ks 16 --sa 1e-6 --out x.h5");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("--size 3kg: key 'surface.generate.size' = \"3kg\": not a length"));
  EXPECT_FALSE(fs::exists(work / "x.h5"));

  r = bad("surface analyze missing.h5");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("missing.h5"));
  fs::create_directories(work);
  std::ofstream(work / "ragged.txt") << "1 2 3\n4 5 6\n7 8\n";
  r = bad("surface analyze ragged.txt --size 1e-3");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("ragged.txt: line 3"));
  EXPECT_EQ(bad("surface").status, 2);
  EXPECT_EQ(bad("surface generate --n 2 --size 1 --hurst 0.5 --kl 1 --ks 1 --sa 1 --out y.h5").status, 2);
}

namespace {
// An ISO 25178-71 SDF (ASCII) measurement of 48 × 32 points, 0.5 µm × 0.25 µm
// steps, one point BAD: what an instrument exports. The heights are
// self-affine (modes of amplitude ∝ |k|^-(1+H), H = 0.8, fixed phases), so
// that the Hurst fit of `surface analyze` is a result, not a refusal.
fs::path measured_sdf(const std::string& name) {
  std::string t = "aISO-1.0\nManufacID = test\nCreateDate = 010120240000\nModDate = 010120240000\n"
                  "NumPoints = 48\nNumProfiles = 32\nXscale = 5e-07\nYscale = 2.5e-07\nZscale = 1e-09\n"
                  "Zresolution = -1\nCompression = 0\nDataType = 7\nCheckType = 0\n*\n";
  const double pi = 3.14159265358979323846;
  auto height = [&](int r, int c) {  // r along y (32 profiles), c along x (48 points); both sides 24 µm / 8 µm
    double h = 0.0;
    for (int kx = -23; kx <= 23; ++kx)
      for (int ky = 0; ky <= 15; ++ky) {
        if (ky == 0 && kx <= 0) continue;
        const double qx = 2 * pi * kx / 24e-6, qy = 2 * pi * ky / 8e-6, q = std::hypot(qx, qy);
        const double phase = 2 * pi * std::fmod(std::abs(std::sin(12.9898 * kx + 78.233 * ky)) * 43758.5453, 1.0);
        h += std::pow(q * 1e-6, -1.8) * std::cos(qx * c * 5e-7 + qy * r * 2.5e-7 + phase);
      }
    return 10.0 * h;  // nm
  };
  for (int r = 0; r < 32; ++r) {
    for (int c = 0; c < 48; ++c) t += r == 7 && c == 11 ? " BAD" : fmt::format(" {:.6f}", height(r, c));
    t += "\n";
  }
  const auto path = work / name;
  fs::create_directories(work);
  std::ofstream(path) << t << "*\n";
  return path;
}
}  // namespace

TEST(SurfaceCli, AnalyzeReadsAnInstrumentFileWithItsSizeAndAsksWhatToDoWithMissingPoints) {
  const auto file = measured_sdf("measured.sdf");
  const auto refused = run_cli("surface analyze '" + file.string() + "'", work);
  EXPECT_EQ(refused.status, 2);
  EXPECT_THAT(refused.err, HasSubstr("1 of 1536 points"));
  EXPECT_THAT(refused.err, HasSubstr("--missing fill"));
  const auto r = run_cli("surface analyze '" + file.string() + "' --missing fill --json", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["format"], "ISO 25178-71 SDF");
  EXPECT_EQ(j["missing_points"], 1);
  EXPECT_EQ(j["grid"]["nx"], 48);
  EXPECT_EQ(j["grid"]["ny"], 32);
  EXPECT_DOUBLE_EQ(j["grid"]["lx"].get<double>(), 48 * 5e-7);
  EXPECT_DOUBLE_EQ(j["grid"]["ly"].get<double>(), 32 * 2.5e-7);
  const auto bad = run_cli("surface analyze '" + file.string() + "' --missing maybe", work);
  EXPECT_EQ(bad.status, 2);
  EXPECT_THAT(bad.err, HasSubstr("--missing maybe: key 'surface.analyze.missing'"));
  EXPECT_THAT(bad.err, HasSubstr("\"refuse\", \"fill\""));
}

TEST(SurfaceCli, AnUnsupportedFormatIsNamedWithTheFormatsThatAreRead) {
  fs::create_directories(work);
  std::ofstream(work / "scan.plu", std::ios::binary) << std::string("\x01\x00\x02 plu", 7);
  const auto r = run_cli("surface analyze scan.plu", work);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("Sensofar (.plu) is not supported"));
  EXPECT_THAT(r.err, HasSubstr("ISO 25178-72 X3P (.x3p)"));
}

TEST(SurfaceCli, ContactTakesAnInstrumentFileAndTheMissingPointsChoice) {
  const auto file = measured_sdf("contact.sdf");
  const std::string base = "contact --surface '" + file.string() + "' --e-star 1e11 --pressure 1e7 --out sdf-contact";
  const auto refused = run_cli(base, work);
  EXPECT_EQ(refused.status, 2);
  EXPECT_THAT(refused.err, HasSubstr("contact.missing"));
  const auto r = run_cli(base + " --missing fill --json", work);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["parameters"]["contact"]["missing"], "fill");
}
