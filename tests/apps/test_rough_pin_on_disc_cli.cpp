// Rough pin and disc in the pin-on-disc model ([scale.macro] pin_surface,
// disc_surface), as physical facts seen from the command line: a roughness
// that tends to nothing gives the smooth model back; a surface written to a file
// is the surface generated in memory (the same heights, bit for bit, and the same run); wear changes
// the roughness it starts from; and a surface the model cannot use is refused
// with status 2 naming the key, the value and what is allowed.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "scratch_dir.hpp"
#include "wearscale/io/topography_io.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_rough_pod_cli_");
const fs::path work = work_scratch.path();
const std::string pin_on_disc = "'" + std::string(WEARSCALE_SOURCE_DIR) + "/cases/pin_on_disc_si_oxide.toml'";
// n = 32 (62.5 µm cells) over the thesis' 2 mm window, through the start of the oxide's wear.
const std::string small = " --set scale.macro.grid=32 --set scale.macro.distance=0.02 --set run.fft_planning=estimate";
// The generated surface of these tests: k = 4…16 of the 2 mm window (λ = 0.5 mm … 125 µm), H = 0.8.
const std::string spectrum = "hurst = 0.8, k_l = 4, k_s = 16, seed = 5";

nlohmann::json run_json(const std::string& args) {
  const auto r = run_cli("run " + args + " --json", work);
  EXPECT_EQ(r.status, 0) << r.err;
  return r.status == 0 ? nlohmann::json::parse(r.out) : nlohmann::json{};
}

double result(const nlohmann::json& j, const std::string& name) { return j["results"][name]["value"].get<double>(); }

// Every number of a CSV's rows (the header skipped), in order.
std::vector<double> numbers(const fs::path& csv) {
  std::vector<double> out;
  const std::string text = slurp(csv);
  std::size_t at = text.find('\n') + 1;
  while (at < text.size()) {
    const std::size_t end = text.find_first_of(",\n", at);
    const std::string cell = text.substr(at, end - at);
    if (!cell.empty()) out.push_back(cell == "nan" ? std::nan("") : std::stod(cell));
    at = end == std::string::npos ? text.size() : end + 1;
  }
  return out;
}
}  // namespace

TEST(RoughPinOnDiscCli, AVanishingRoughnessGivesTheSmoothModelBack) {
  // h'_RMS = 1e-10 (1e-9 of a slope of 0.1): heights of about 1e-15 m on the pin, and on the resolved disc.
  for (const std::string track : {"averaged", "resolved"}) {
    SCOPED_TRACE(track);
    const std::string base = pin_on_disc + small + " --set scale.macro.track=" + track;
    const auto smooth = run_json(base + " --out smooth-" + track);
    std::string rough_args = base + " --set 'scale.macro.pin_surface={" + spectrum + ", hprime_rms = 1e-10}'";
    if (track == "resolved") rough_args += " --set 'scale.macro.disc_surface={" + spectrum + ", hprime_rms = 1e-10}'";
    const auto rough = run_json(rough_args + " --out rough-" + track);
    ASSERT_FALSE(smooth.empty());
    ASSERT_FALSE(rough.empty());
    for (const char* name : {"mu_mean", "pin_wear", "disc_wear"})
      EXPECT_NEAR(result(rough, name), result(smooth, name), 5e-3 * std::abs(result(smooth, name))) << name;
    EXPECT_FALSE(fs::exists(work / ("smooth-" + track) / "roughness.csv")) << "a smooth run's outputs are as they were";
    EXPECT_TRUE(fs::exists(work / ("rough-" + track) / "roughness.csv"));
  }
}

TEST(RoughPinOnDiscCli, ASurfaceWrittenToAFileIsTheSurfaceGeneratedInMemory) {
  // The same surface by `surface generate` (HDF5, the surfaces' writer), then as a plain text grid in full precision.
  // Both programs plan their FFTs by estimate, as the runs do: plans measured in one process may round otherwise.
  const auto g = run_cli("surface generate --n 32 --size '2 mm' --hurst 0.8 --kl 4 --ks 16 --seed 5 --sa 5e-7 "
                         "--set run.fft_planning=estimate --out surf --json",
                         work);
  ASSERT_EQ(g.status, 0) << g.err;
  const fs::path h5 = work / "surf" / "surface.h5";
  ASSERT_TRUE(fs::exists(h5));
  const wearscale::RealField h = wearscale::bem::read_topography_h5(h5);
  {
    std::ofstream text(work / "surface.txt");
    text << fmt::format("# lx = {:.17g}\n# ly = {:.17g}\n", h.grid().lx, h.grid().ly);
    for (std::size_t i = 0; i < h.grid().nx; ++i)
      for (std::size_t j = 0; j < h.grid().ny; ++j) text << fmt::format("{:.17g}{}", h(i, j), j + 1 < h.grid().ny ? " " : "\n");
  }
  const auto memory = run_json(pin_on_disc + small + " --set 'scale.macro.pin_surface={" + spectrum +
                               ", sa = 5e-7}' --out memory");
  const auto from_h5 = run_json(pin_on_disc + small +
                                " --set 'scale.macro.pin_surface={file = \"surf/surface.h5\", level = \"mean\"}' --out h5");
  const auto from_text =
      run_json(pin_on_disc + small + " --set 'scale.macro.pin_surface={file = \"surface.txt\", level = \"mean\"}' --out text");
  ASSERT_FALSE(memory.empty());
  for (const auto* other : {&from_h5, &from_text}) {
    ASSERT_FALSE(other->empty());
    // The same heights, bit for bit: the surface's own figures, computed from every height, are equal.
    for (const char* name : {"pin_surface_sq", "pin_surface_hprime_rms"})
      EXPECT_EQ(result(*other, name), result(memory, name)) << name;
    // The same run, bit for bit: each process plans its FFTs alike (by estimate, the generated surface's too).
    for (const char* name : {"mu_mean", "mu_final", "pin_wear", "disc_wear", "pin_sq_final", "contact_solves"})
      EXPECT_EQ(result(*other, name), result(memory, name)) << name;
  }
  for (const char* file : {"friction.csv", "roughness.csv"})
    for (const char* other : {"h5", "text"}) {
      const auto a = numbers(work / other / file), b = numbers(work / "memory" / file);
      ASSERT_EQ(a.size(), b.size()) << file;
      for (std::size_t k = 0; k < a.size(); ++k)
        if (!(std::isnan(a[k]) && std::isnan(b[k]))) ASSERT_EQ(a[k], b[k]) << other << " " << file << " value " << k;
    }
  // The surface the model starts from is the one asked for: Sa = 0.5 µm over the whole window.
  EXPECT_NEAR(result(memory, "pin_surface_sq"), 0.5e-6 * std::sqrt(std::numbers::pi / 2.0), 0.15 * 0.5e-6);
}

TEST(RoughPinOnDiscCli, AFinerFileIsAveragedOverEachCell) {
  // 64 points over 2 mm onto 32 cells: each cell the mean of 2 × 2 samples. The averaging keeps the long
  // wavelengths (k = 4 to 16: 8 to 2 cells) and damps the short ones, so the heights' RMS drops, a little.
  const auto g = run_cli("surface generate --n 64 --size '2 mm' --hurst 0.8 --kl 4 --ks 16 --seed 2 --sa 5e-7 "
                         "--out fine --json",
                         work);
  ASSERT_EQ(g.status, 0) << g.err;
  const double file_sq = nlohmann::json::parse(g.out)["results"]["h_rms"]["value"].get<double>();
  const auto j = run_json(pin_on_disc + " --set scale.macro.grid=32 --set scale.macro.distance=0.001 "
                          "--set 'scale.macro.pin_surface={file = \"fine/surface.h5\", level = \"mean\"}' --out fine-run");
  ASSERT_FALSE(j.empty());
  EXPECT_LT(result(j, "pin_surface_sq"), file_sq);
  EXPECT_GT(result(j, "pin_surface_sq"), 0.9 * file_sq);
}

TEST(RoughPinOnDiscCli, WearSmoothsTheRoughPinInItsScarAndTheTableSaysSo) {
  // A rough pin (Sa 0.5 µm at 62.5-250 µm wavelengths) on bulk SiO2 over 0.05 m: the scar's
  // asperities are worn down, so the scar's Sq at the end is below the surface's.
  const auto j = run_json(pin_on_disc + " --set scale.macro.grid=32 --set scale.macro.distance=0.05 "
                          "--set run.fft_planning=estimate --set materials.layer.thickness=inf "
                          "--set 'scale.macro.pin_surface={" + spectrum + ", sa = \"0.5 um\"}' --out worn");
  ASSERT_FALSE(j.empty());
  EXPECT_LT(result(j, "pin_sq_final"), result(j, "pin_surface_sq"));
  const std::string csv = slurp(work / "worn" / "roughness.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "distance_m,pin_sa_m,pin_sq_m,pin_hprime_rms,pin_region_cells,disc_sa_m,disc_sq_m,disc_hprime_rms,"
            "disc_region_cells");
  EXPECT_THAT(slurp(work / "worn" / "roughness.csv.json"), HasSubstr("least-squares quadric"));
}

struct BadSurface {
  std::string name, args, key, words;
};
void PrintTo(const BadSurface& b, std::ostream* os) { *os << b.name; }
class RoughPinOnDiscCliBadSurface : public ::testing::TestWithParam<BadSurface> {};

TEST_P(RoughPinOnDiscCliBadSurface, ExitsWithStatus2NamingTheKeyAndWritesNothing) {
  const auto& p = GetParam();
  if (p.name == "too_small" || p.name == "too_coarse") {
    // 1 mm (smaller than the 2 mm window), and 16 points over 2 mm (125 µm, coarser than the 62.5 µm cells).
    const std::string size = p.name == "too_small" ? "'1 mm' --n 32" : "'2 mm' --n 16";
    const auto g = run_cli("surface generate --size " + size + " --hurst 0.8 --kl 2 --ks 8 --sa 5e-7 --out " + p.name,
                           work);
    ASSERT_EQ(g.status, 0) << g.err;
  }
  const auto out = work / ("bad-" + p.name);
  const auto r = run_cli("run " + pin_on_disc + small + " --out '" + out.string() + "' " + p.args, work);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr(p.key));
  EXPECT_THAT(r.err, HasSubstr(p.words));
  EXPECT_FALSE(fs::exists(out));
}

INSTANTIATE_TEST_SUITE_P(
    Keys, RoughPinOnDiscCliBadSurface,
    ::testing::Values(
        BadSurface{"missing_file", "--set scale.macro.pin_surface=no_such_surface.x3p", "scale.macro.pin_surface",
                   "no_such_surface.x3p"},
        BadSurface{"too_small", "--set 'scale.macro.pin_surface=\"too_small/surface.h5\"'", "scale.macro.pin_surface",
                   "smaller than the pin's window of 0.002 m × 0.002 m"},
        BadSurface{"too_coarse", "--set 'scale.macro.pin_surface=\"too_coarse/surface.h5\"'",
                   "scale.macro.pin_surface", "a sampling step of at most size/grid = 6.25e-05 m"},
        BadSurface{"bad_hurst", "--set 'scale.macro.pin_surface={hurst = 1.5, k_l = 4, k_s = 16, sa = \"0.5 um\"}'",
                   "scale.macro.pin_surface.hurst", "(0, 1]"},
        BadSurface{"above_nyquist", "--set 'scale.macro.pin_surface={hurst = 0.8, k_l = 4, k_s = 64, sa = \"0.5 um\"}'",
                   "scale.macro.pin_surface.k_s", "[4, 16]"},
        BadSurface{"no_target", "--set 'scale.macro.pin_surface={hurst = 0.8, k_l = 4, k_s = 16}'",
                   "scale.macro.pin_surface.hprime_rms", "one roughness target"},
        BadSurface{"rough_disc_on_the_averaged_track",
                   "--set 'scale.macro.disc_surface={hurst = 0.8, k_l = 4, k_s = 16, sa = \"0.5 um\"}'",
                   "scale.macro.disc_surface", "track = \"resolved\""}),
    [](const auto& p) { return p.param.name; });

TEST(RoughPinOnDiscCli, TheAdaptiveIntegratorOnARoughDiscOverAnOxideWarnsThatItIsNotVerified) {
  // Measured 3-4 % off the converged explicit stepping there (docs/pin_on_disc.md); on bare Si one
  // material slides at μ0 whatever the step, and the explicit stepping is the reference: no warning.
  const std::string base = pin_on_disc + " --set scale.macro.grid=16 --set scale.macro.distance=0.001" +
                           " --set run.fft_planning=estimate --set scale.macro.track=resolved" +
                           " --set 'scale.macro.disc_surface={hurst = 0.8, k_l = 4, k_s = 8, seed = 5, sa = \"0.5 um\"}'";
  const auto adaptive = run_cli("run " + base + " --set scale.macro.integrator=adaptive", work / "warn_adaptive");
  EXPECT_EQ(adaptive.status, 0) << adaptive.err;
  EXPECT_THAT(adaptive.err, HasSubstr("adaptive integrator on a rough disc over an oxide layer is not verified"));
  const auto bare = run_cli("run " + base + " --set scale.macro.integrator=adaptive --set materials.layer.thickness=0",
                            work / "warn_bare");
  EXPECT_EQ(bare.status, 0) << bare.err;
  EXPECT_THAT(bare.err, ::testing::Not(HasSubstr("not verified")));
  const auto stepped = run_cli("run " + base + " --set scale.macro.integrator=explicit", work / "warn_explicit");
  EXPECT_EQ(stepped.status, 0) << stepped.err;
  EXPECT_THAT(stepped.err, ::testing::Not(HasSubstr("not verified")));
}
