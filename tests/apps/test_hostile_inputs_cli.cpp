// The program as a hostile user meets it: every input that used
// to crash it (segfault, std::bad_alloc, exit 3), run until memory ran out
// or gave a silently wrong answer is refused with exit 2 (bad input) or 1
// (a result outside physical bounds), a message naming the file, key or
// value, and nothing written. Then what must work despite unusual input
// (h5py tables, a byte-order mark, relative paths, string sweeps), and what
// the output folder guarantees (one writer, a fresh run never discards a
// checkpoint, a damaged checkpoint is refused, threads in the resume hint).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <functional>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "h5_fixture.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

namespace {
const ScratchDir work_scratch("wearscale_hostile_");
const std::filesystem::path work = work_scratch.path();
const std::string source = WEARSCALE_SOURCE_DIR;
const std::string pin_on_disc = source + "/cases/pin_on_disc_si_oxide.toml";
const std::string small = " --set scale.macro.grid=32 --set scale.macro.distance=0.001 --set run.fft_planning=estimate";

void write_file(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

// A topography file as another tool writes it: 8 × 8 heights, with `attributes` applied.
void topography(const fs::path& file, double scale, bool constant,
                const std::function<void(h5fixture::File&)>& attributes) {
  std::vector<double> h(64);
  for (std::size_t k = 0; k < h.size(); ++k) h[k] = constant ? 5.0 : scale * 1e-7 * std::sin(0.7 * k) * std::cos(0.3 * k);
  h5fixture::File f(file);
  f.dataset("/surface/height", {8, 8}, h);
  attributes(f);
}

void with_size(h5fixture::File& f) {
  f.number_attribute("/surface/height", "lx", {1e-4});
  f.number_attribute("/surface/height", "ly", {1e-4});
}

// The pin-on-disc case with a [sweep] table appended.
std::string sweep_case(const std::string& sweep) {
  return slurp(pin_on_disc) + "\n[sweep]\n" + sweep + "\nparallel = false\n";
}
}  // namespace

// ---------------------------------------------------------------------------
// Refusals: one row per reproduction of the issue.

struct Hostile {
  std::string name;
  std::string args;                            ///< OUT is the output folder (must stay absent)
  std::function<void(const fs::path&)> setup;  ///< files written into the work folder first
  int status;                                  ///< 2 bad input, 1 a result outside physical bounds
  std::vector<std::string> expected;           ///< in the message
  std::string env = {};                        ///< variables for the run
};
void PrintTo(const Hostile& h, std::ostream* os) { *os << h.name; }

class HostileInput : public ::testing::TestWithParam<Hostile> {};

TEST_P(HostileInput, IsRefusedWithItsExitStatusNamingTheProblemAndWritesNothing) {
  const auto& p = GetParam();
  const auto dir = work / ("hostile-" + p.name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  if (p.setup) p.setup(dir);
  std::string args = p.args;
  if (const auto at = args.find("OUT"); at != std::string::npos) args.replace(at, 3, "out");
  const auto r = run_cli(args, dir, p.env);
  EXPECT_EQ(r.status, p.status) << r.err;
  for (const auto& e : p.expected) EXPECT_THAT(r.err, HasSubstr(e));
  EXPECT_THAT(r.err, Not(HasSubstr("internal error")));
  EXPECT_FALSE(fs::exists(dir / "out")) << "nothing may be written";
  fs::remove_all(dir);
}

namespace {
const std::string contact_h5 = "contact --surface h.h5 --e-star 1e9 --pressure 1e6 --out OUT";
const std::string generate = "surface generate --size 1e-3 --hurst 0.8 --kl 1 --ks 4 --seed 1 ";
auto h5_with(double scale, bool constant, std::function<void(h5fixture::File&)> attributes) {
  return [=](const fs::path& dir) { topography(dir / "h.h5", scale, constant, attributes); };
}
auto text_file(const std::string& name, std::string text) {
  return [=](const fs::path& dir) { write_file(dir / name, text); };
}
const std::string table_head = "# material: Si\npressure_GPa,sigma_max_GPa,sigma_dyn_GPa\n";
}  // namespace

INSTANTIATE_TEST_SUITE_P(
    EveryReader, HostileInput,
    ::testing::Values(
        // HDF5 topographies: attributes and declared sizes checked before they are read.
        Hostile{"lx_array_of_1000", contact_h5,
                h5_with(1.0, false, [](auto& f) { f.number_attribute("/surface/height", "lx", std::vector<double>(1000, 1e-4)); }),
                2, {"h.h5: attribute 'lx' on '/surface/height' holds 1000 values", "allowed: one"}},
        Hostile{"lx_array_of_4", "surface analyze h.h5 --psd-out OUT/psd.csv",
                h5_with(1.0, false, [](auto& f) { f.number_attribute("/surface/height", "lx", {1e-4, 2e-4, 3e-4, 4e-4}); }),
                2, {"holds 4 values"}},
        Hostile{"lx_string", contact_h5,
                h5_with(1.0, false, [](auto& f) { f.string_attribute("/surface/height", "lx", "0.1 mm"); }), 2,
                {"attribute 'lx' on '/surface/height' is the string '0.1 mm'; allowed: one number"}},
        Hostile{"dataset_of_200000_squared", contact_h5,
                [](const fs::path& dir) { h5fixture::File(dir / "h.h5").dataset("/surface/height", {200000, 200000}, {}); },
                2, {"h.h5: dataset '/surface/height': a grid of 200000 × 200000 points is larger than allowed"}},
        Hostile{"heights_times_1e300", contact_h5, h5_with(1e300, false, with_size), 2,
                {"h.h5: dataset '/surface/height': heights from", "are heights and sizes in the same unit?"}},
        Hostile{"constant_surface", "surface analyze h.h5 --psd-out OUT/psd.csv", h5_with(1.0, true, with_size), 2,
                {"h.h5: the topography is flat"}},
        // Sizes within their ranges but beyond the machine (the limit is set so the rows hold on any CI machine).
        Hostile{"generate_65536", generate + "--n 65536 --hprime-rms 1 --out OUT/s.h5", {}, 2,
                {"a 65536 × 65536 surface needs 192 GiB", "give a smaller --n"}, "WEARSCALE_MEMORY_LIMIT=16GiB"},
        Hostile{"contact_grid_16384",
                "contact --set contact.grid=16384 --set contact.size=1e-3 --set contact.sphere.radius=1e-2 "
                "--e-star 1e9 --pressure 1e6 --out OUT",
                {}, 2, {"key 'contact.grid' = 16384: a contact study of 16384 × 16384 points needs 40 GiB"},
                "WEARSCALE_MEMORY_LIMIT=16GiB"},
        Hostile{"hprime_rms_1e308", generate + "--n 16 --hprime-rms 1e308 --out OUT/s.h5", {}, 2,
                {"--hprime-rms 1e308: key 'surface.generate.hprime_rms'", "allowed: (0, 100]"}},
        Hostile{"rough_shear_length_20",
                "dem rough-shear --material SiO2 --d0 3e-9 --length 20 --out OUT", {}, 2,
                {"a DEM sample of about", "particles (box 20 ×", "lengths are in metres"}},
        Hostile{"trapped_particles_length_20",
                "dem trapped-particles --material SiO2 --n 2 --D 20e-9 --d0 '6 nm' --length 20 --out OUT", {}, 2,
                {"a DEM sample of about", "particles (box 20 ×"}},
        Hostile{"dem_poisson_0.5", "dem patch-test --nu 0.5 --out OUT", {}, 2,
                {"key 'dem.poisson' = 0.5", "allowed: -1 < ν ≤ 0.25"}},
        // A grid within the readers' cap (2^28 points) but beyond the memory limit: refused before it is
        // allocated (the text formats are also bounded by their length; HDF5 and X3P data may be compressed).
        Hostile{"dataset_of_12000_squared", contact_h5,
                [](const fs::path& dir) { h5fixture::File(dir / "h.h5").dataset("/surface/height", {12000, 12000}, {}); },
                2, {"h.h5: dataset '/surface/height' (12000 × 12000 heights) needs 3.35 GiB", "this process may use"},
                "WEARSCALE_MEMORY_LIMIT=2GiB"},
        // A device is not a topography file.
        Hostile{"topography_dev_zero", "surface analyze /dev/zero --psd-out OUT/psd.csv", {}, 2,
                {"/dev/zero: not a regular file"}},
        // Case files that are not files.
        Hostile{"run_dev_zero", "run /dev/zero --out OUT", {}, 2, {"/dev/zero: not a regular file"}},
        // Found by fuzz_sweep: bytes that are not UTF-8 cannot go into summary.json (exit 3 before).
        Hostile{"set_not_utf8", "run '" + pin_on_disc + "'" + small + " --out OUT --set \"$(printf 'case.name=a\\373b')\"",
                {}, 2, {"--set: \"case.name=a\uFFFDb\" is not valid UTF-8"}},
        Hostile{"out_not_utf8", "run '" + pin_on_disc + "'" + small + " --out \"$(printf 'OUT\\373')\"", {}, 2,
                {"--out", "the path is not valid UTF-8"}},
        Hostile{"multi_line_set", "run '" + pin_on_disc + "' --out OUT --set \"$(printf 'scale.macro.grid=32\\nscale.macro.size=1')\"",
                {}, 2, {"key 'scale.macro.grid': the value spans several lines"}},
        // Physics bounds of the macroscale.
        Hostile{"time_step_1e10_s", "run '" + pin_on_disc + "' --set 'scale.macro.time_step=\"1e10 s\"' --out OUT", {}, 2,
                {"key 'scale.macro.time_step' = \"1e10 s\": out of range; allowed: (0, 62.5] s"}},
        Hostile{"window_smaller_than_the_pin", "run '" + pin_on_disc + "'" + small + " --set 'scale.macro.size=\"1 um\"' --out OUT",
                {}, 2, {"the contact reaches the edge of the window (size = 1e-06 m"}},
        Hostile{"distance_zero", "run '" + pin_on_disc + "' --set scale.macro.distance=0 --out OUT", {}, 2,
                {"key 'scale.macro.distance' = 0: out of range; allowed: > 0 m"}},
        Hostile{"table_never_reaching_p_crit", "run '" + pin_on_disc + "'" + small + " --set scale.molecular.tables.Si=si.csv --out OUT",
                text_file("si.csv", table_head + "0,10,1\n5,12,1\n"), 2,
                {"si.csv: σ_max(p) > p up to the end of the table (5 GPa)", "p_crit"}},
        // Sweeps: every run checked before any starts.
        Hostile{"sweep_duplicate_values", "run sweep.toml --out OUT",
                text_file("sweep.toml", sweep_case("key = \"materials.layer.thickness\"\nvalues = [1e-6, 1e-6]")), 2,
                {"key 'sweep.values'", "values 1 ('1e-06') and 2 ('1e-06') are the same run"}},
        Hostile{"sweep_equal_quantities", "run sweep.toml --out OUT",
                text_file("sweep.toml", sweep_case("key = \"materials.layer.thickness\"\nvalues = [1e-6, \"1 um\"]")), 2,
                {"are the same run"}},
        Hostile{"sweep_over_output_dir", "run sweep.toml --out OUT",
                text_file("sweep.toml", sweep_case("key = \"output.dir\"\nvalues = [\"a\", \"b\"]")), 2,
                {"key 'sweep.key'", "[output] cannot be swept"}},
        Hostile{"sweep_table_empty", "run sweep.toml --out OUT",
                text_file("sweep.toml", sweep_case("key = \"materials.layer.thickness\"\nvalues = [0]\ntable = \"\"")), 2,
                {"key 'sweep.table' = \"\": not a file name for the sweep table"}},
        Hostile{"sweep_table_folder", "run sweep.toml --out OUT",
                text_file("sweep.toml", sweep_case("key = \"materials.layer.thickness\"\nvalues = [0]\ntable = \"sub/\"")), 2,
                {"key 'sweep.table' = \"sub/\""}},
        Hostile{"sweep_value_out_of_range", "run sweep.toml --out OUT",
                text_file("sweep.toml", sweep_case("key = \"materials.layer.thickness\"\nvalues = [0, -1e-6]")), 2,
                {"sweep.toml:", "(sweep.values[1]): key 'materials.layer.thickness' = -1e-06: out of range"}},
        // Output folders that cannot be written: checked before the work, named.
        Hostile{"run_into_proc_self", "run '" + pin_on_disc + "'" + small + " --out /proc/self", {}, 2,
                {"/proc/self: cannot write into it"}},
        Hostile{"contact_into_proc_self",
                "contact --set contact.grid=16 --set contact.size=1e-3 --set contact.sphere.radius=1e-2 --e-star 1e9 "
                "--pressure 1e6 --out /proc/self",
                {}, 2, {"/proc/self: cannot write into it"}},
        Hostile{"wearmap_into_proc_self", "wearmap analytic2d --n 4 --out /proc/self", {}, 2,
                {"/proc/self: cannot write into it"}},
        Hostile{"generate_into_proc_self", generate + "--n 16 --hprime-rms 1 --out /proc/self/s.h5", {}, 2,
                {"output folder /proc/self/s.h5: cannot create it"}},
        Hostile{"dem_into_proc_self", "dem patch-test --nu 0.1 --length 8 --out /proc/self", {}, 2,
                {"/proc/self: cannot write into it"}}),
    [](const auto& p) {
      std::string n = p.param.name;
      for (auto& c : n)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return n;
    });

// A generated surface written without its k attributes (another tool's copy):
// the default band runs past the shortest wavelength, whose windowed PSD fits
// H ≈ 7. Not a Hurst exponent: no `hurst` result, the fit reported as failed
// with what to do (a warning and summary.json's hurst_fit), and the rest of
// the analysis (Sa, h_RMS, h'_RMS, the PSD) written: exit 0, the fit being
// optional to the user.
TEST(HostileInput, AHurstExponentOutsideZeroToOneIsNeverAResult) {
  const auto dir = work / "hurst";
  auto r = run_cli("surface generate --n 128 --size 1e-3 --hurst 0.8 --kl 2 --kr 4 --ks 32 --hprime-rms 0.1 --seed 1 "
                   "--out gen --file s.h5",
                   dir);
  ASSERT_EQ(r.status, 0) << r.err;
  r = run_cli("surface analyze gen/s.h5 --no-window --json", dir);  // with its k attributes: the band is known
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(nlohmann::json::parse(r.out)["hurst"].get<double>(), 0.8, 0.02);
  {
    // The heights alone, as h5py would copy them.
    const auto h = wearscale::H5Reader(dir / "gen" / "s.h5").read_series("/surface/height");
    h5fixture::File out(dir / "copy.h5");
    out.dataset("/surface/height", {128, 128}, h);
    out.number_attribute("/surface/height", "lx", {1e-3});
  }
  r = run_cli("surface analyze copy.h5 --psd-out psd.csv --out copy --json", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("outside (0, 1]: that band is not self-affine"));
  EXPECT_THAT(r.err, HasSubstr("--qmin and --qmax"));
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["hurst"].is_null());
  EXPECT_EQ(j["hurst_fit"]["status"], "failed");
  EXPECT_THAT(j["hurst_fit"]["reason"].get<std::string>(), HasSubstr("not self-affine"));
  EXPECT_FALSE(j["results"].contains("hurst"));
  for (const char* kept : {"Sa", "h_rms", "h_prime_rms"}) EXPECT_GT(j["results"][kept]["value"].get<double>(), 0.0) << kept;
  EXPECT_TRUE(fs::exists(dir / "copy" / "psd.csv"));
  EXPECT_GT(wearscale::H5Reader(dir / "copy" / "run.h5").read_series("/psd/C").size(), 10u);
  r = run_cli("surface analyze copy.h5 --qmin 5e4 --qmax 2e5", dir);  // the self-affine band, given
  EXPECT_EQ(r.status, 0) << r.err;
  fs::remove_all(dir);
}

// ---------------------------------------------------------------------------
// Unusual inputs that must work.

TEST(UnusualInput, AStrengthTableFromASpreadsheetWithAByteOrderMarkIsRead) {
  const auto dir = work / "bom";
  write_file(dir / "si.csv", "\xEF\xBB\xBF" + table_head + "0,10,1.5\n5,9,1.5\n10.6,10.6,1.5\n12,8,1.5\n");
  const auto r = run_cli("run '" + pin_on_disc + "'" + small + " --set scale.molecular.tables.Si=si.csv --out out", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, Not(HasSubstr("missing column")));
  fs::remove_all(dir);
}

// h5py writes string attributes as variable-length strings; pressures in GPa with their unit.
TEST(UnusualInput, AStrengthTableWrittenByH5pyIsRead) {
  const auto dir = work / "h5py";
  {
    h5fixture::File f(dir / "si.h5");
    f.dataset("/strength/pressure", {4}, {0.0, 5.0, 10.6, 12.0});
    f.dataset("/strength/sigma_max", {4}, {10.0, 9.0, 10.6, 8.0});
    f.dataset("/strength/sigma_dyn", {4}, {1.5, 1.5, 1.5, 1.5});
    for (const char* c : {"pressure", "sigma_max", "sigma_dyn"})
      f.string_attribute(std::string("/strength/") + c, "unit", "GPa");
    f.string_attribute("/strength", "provenance_keys", "material,source");
    f.string_attribute("/strength", "material", "Si");
    f.string_attribute("/strength", "source", "h5py");
  }
  const auto r =
      run_cli("run '" + pin_on_disc + "'" + small + " --set scale.molecular.tables.Si=si.h5 --out out --json", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto results = nlohmann::json::parse(r.out)["results"];
  EXPECT_NEAR(results["p_crit_SiO2-Si"]["value"].get<double>(), 10.6e9, 1e6);  // σ_max = p at 10.6 GPa
  EXPECT_NEAR(results["mu0_SiO2-Si"]["value"].get<double>(), 1.5 / 10.6, 1e-6);
  fs::remove_all(dir);
}

// A path in a case file is relative to that file, not to where the program runs.
TEST(UnusualInput, ATablePathInACaseFileIsRelativeToTheCaseFile) {
  const auto dir = work / "relative";
  write_file(dir / "cases" / "si.csv", table_head + "0,10,1.5\n5,9,1.5\n10.6,10.6,1.5\n12,8,1.5\n");
  std::string text = slurp(pin_on_disc);
  const auto at = text.find("[scale.molecular]");
  ASSERT_NE(at, std::string::npos);
  text.insert(text.find('\n', at) + 1, "tables = { Si = \"si.csv\" }\n");
  write_file(dir / "cases" / "case.toml", text);
  auto r = run_cli("run cases/case.toml" + small + " --out out --json", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(nlohmann::json::parse(r.out)["results"]["mu0_SiO2-Si"]["value"].get<double>(), 1.5 / 10.6, 1e-6);
  fs::remove_all(dir);
}

TEST(UnusualInput, ASweepOverAStringKeyWritesTheValuesAsText) {
  const auto dir = work / "string-sweep";
  write_file(dir / "sweep.toml", sweep_case("key = \"case.name\"\nvalues = [\"first, try\", \"second\"]"));
  const auto r = run_cli("run sweep.toml" + small + " --out out", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string table = slurp(dir / "out" / "sweep.csv");
  EXPECT_THAT(table, HasSubstr("\n\"first, try\","));
  EXPECT_THAT(table, HasSubstr("\nsecond,"));
  fs::remove_all(dir);
}

// A step longer than the distance over the step count asked for: the last one lands on the distance.
TEST(UnusualInput, ALongTimeStepCoversExactlyTheDistanceAskedFor) {
  const auto dir = work / "long-step";
  const auto r = run_cli("run '" + pin_on_disc + "' --set scale.macro.grid=32 --set 'scale.macro.time_step=\"10 s\"' "
                         "--set scale.macro.distance=0.5 --set scale.macro.integrator=explicit --out out --json",
                         dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto results = nlohmann::json::parse(r.out)["results"];
  EXPECT_NEAR(results["distance"]["value"].get<double>(), 0.5, 1e-12);  // 6 steps of 0.08 m and one of 0.02 m
  EXPECT_EQ(results["contact_solves"]["value"].get<double>(), 8);
  fs::remove_all(dir);
}

// ---------------------------------------------------------------------------
// The output folder.

TEST(OutputFolder, ASecondRunIntoAFolderInUseIsRefusedNamingTheHoldersPid) {
  const auto dir = work / "busy";
  fs::create_directories(dir);
  const std::string slow = "run '" + pin_on_disc + "' --set scale.macro.grid=64 --set scale.macro.distance=0.3 --out out";
  const std::string cmd = "cd '" + dir.string() + "' && CI=true exec '" + std::string(WEARSCALE_CLI) + "' " + slow +
                          " >first.out 2>first.err";
  const pid_t first = spawn_shell(cmd);
  for (int k = 0; k < 3000 && !fs::exists(dir / "out" / ".wearscale.lock"); ++k) ::usleep(10000);
  ASSERT_TRUE(fs::exists(dir / "out" / ".wearscale.lock")) << slurp(dir / "first.err");
  const auto r = run_cli(slow, dir);
  ::kill(first, SIGKILL);
  int status = 0;
  ::waitpid(first, &status, 0);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("out is being written by process " + std::to_string(first)));
  EXPECT_THAT(r.err, HasSubstr("wearscale run"));
  fs::remove_all(dir);
}

TEST(OutputFolder, AFreshRunNeverDiscardsTheCheckpointOfAnUnfinishedOne) {
  const auto dir = work / "fresh";
  write_file(dir / "out" / "checkpoint.h5", "the state of a run that was killed\n");
  const auto r = run_cli("run '" + pin_on_disc + "'" + small + " --out out", dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("out holds the checkpoint of an unfinished run; continue it with --resume out"));
  EXPECT_EQ(slurp(dir / "out" / "checkpoint.h5"), "the state of a run that was killed\n");
  fs::remove_all(dir);
}

// A run killed after its checkpoint: flipped bytes in it are refused on
// resume; the intact one resumes, and resuming the completed run says it
// kept the files rather than wrote them.
TEST(OutputFolder, ADamagedCheckpointIsRefusedAndAnIntactOneResumes) {
  const auto dir = work / "damaged";
  const std::string args = "run '" + pin_on_disc + "' --set scale.macro.grid=32 --set scale.macro.distance=0.05 "
                           "--set run.fft_planning=estimate --set run.checkpoint_steps=20 --out out";
  const std::string cmd = "cd '" + dir.string() + "' && CI=true exec '" + std::string(WEARSCALE_CLI) + "' " + args +
                          " >killed.out 2>killed.err";
  fs::create_directories(dir);
  const pid_t run = spawn_shell(cmd);
  for (int k = 0; k < 6000 && !fs::exists(dir / "out" / "checkpoint.h5"); ++k) ::usleep(5000);
  ::kill(run, SIGKILL);
  int status = 0;
  ::waitpid(run, &status, 0);
  ASSERT_TRUE(fs::exists(dir / "out" / "checkpoint.h5")) << slurp(dir / "killed.err");
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it was killed";
  const std::string intact = slurp(dir / "out" / "checkpoint.h5");
  std::string damaged = intact;
  for (std::size_t k = 0; k < 64; ++k) damaged[damaged.size() / 2 + k] ^= 0x20;
  write_file(dir / "out" / "checkpoint.h5", damaged);
  const std::string resume = "run '" + pin_on_disc + "' --set scale.macro.grid=32 --set scale.macro.distance=0.05 "
                             "--set run.fft_planning=estimate --set run.checkpoint_steps=20 --resume out";
  auto r = run_cli(resume, dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("checkpoint.h5"));
  EXPECT_FALSE(fs::exists(dir / "out" / "summary.json"));
  write_file(dir / "out" / "checkpoint.h5", intact);
  r = run_cli(resume, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("resuming macro/bem-pin-on-disc"));
  r = run_cli(resume, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("kept out/run.h5"));
  EXPECT_THAT(r.err, Not(HasSubstr("wrote")));
  fs::remove_all(dir);
}

// -j is the thread budget of a sweep too, and the resume hint repeats it.
TEST(OutputFolder, ASweepHonoursTheThreadCountAndTheResumeHintRepeatsIt) {
  const auto dir = work / "threads";
  write_file(dir / "sweep.toml", slurp(pin_on_disc) + "\n[sweep]\nkey = \"materials.layer.thickness\"\nvalues = [0, 1e-6, 2e-6]\n");
  const auto r = run_cli("run sweep.toml -j 1" + small + " --out out", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("3 runs on 1 worker(s) × 1 thread(s)"));
  fs::remove_all(dir);
}

// A run killed while it writes over an older run's folder leaves that run's
// outputs whole and matching its summary (and its own checkpoint beside them).
TEST(OutputFolder, ARunKilledOverAnOlderRunLeavesTheOlderSetIntact) {
  const auto dir = work / "over";
  const std::string base = "run '" + pin_on_disc + "' --set scale.macro.grid=32 --set run.fft_planning=estimate";
  auto r = run_cli(base + " --set scale.macro.distance=0.002 --out out", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string summary = slurp(dir / "out" / "summary.json"), csv = slurp(dir / "out" / "friction.csv");
  const std::string cmd = "cd '" + dir.string() + "' && CI=true exec '" + std::string(WEARSCALE_CLI) + "' " + base +
                          " --set scale.macro.distance=0.05 --set run.checkpoint_steps=20 --out out >b.out 2>b.err";
  const pid_t b = spawn_shell(cmd);
  for (int k = 0; k < 6000 && !fs::exists(dir / "out" / "checkpoint.h5"); ++k) ::usleep(5000);
  ::kill(b, SIGKILL);
  int status = 0;
  ::waitpid(b, &status, 0);
  ASSERT_TRUE(fs::exists(dir / "out" / "checkpoint.h5")) << slurp(dir / "b.err");
  EXPECT_EQ(slurp(dir / "out" / "summary.json"), summary) << "the older run's summary stands";
  EXPECT_EQ(slurp(dir / "out" / "friction.csv"), csv) << "and its outputs, unmixed";
  r = run_cli(base + " --set scale.macro.distance=0.002 --resume out", dir);  // the older run: complete and intact
  EXPECT_EQ(r.status, 2) << "the checkpoint belongs to the killed run, not to this case: " << r.err;
  EXPECT_THAT(r.err, HasSubstr("key 'scale.macro.distance' was 0.05, is now 0.002"));
  fs::remove_all(dir);
}

// Whatever the DEM measures, an E ≤ 0 or a ν outside (−1, 0.5) is never a
// result: d0 = 60 (above d_min = 30) measured E = −0.40…2.07, ν = −1.78…2.20.
// Exit 1 (the command's guard) or 2 (d0 refused), never 0.
TEST(HostileInput, ANonsensicalPatchTestMeasurementIsNeverAResult) {
  const auto dir = work / "patch-d0";
  const auto r = run_cli("dem patch-test --nu 0.1 --d0 60 --length 6 --no-strengths --out out --json", dir);
  if (r.status == 0) {
    const auto results = nlohmann::json::parse(r.out)["results"];
    const double e = results["young"]["value"].get<double>(), nu = results["poisson"]["value"].get<double>();
    EXPECT_GT(e, 0.0);
    EXPECT_GT(nu, -1.0);
    EXPECT_LT(nu, 0.5);
  } else {
    EXPECT_TRUE(r.status == 1 || r.status == 2) << r.status << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir / "out" / "summary.json"));
  }
  fs::remove_all(dir);
}
