// The program against hostile inputs by class, as a careless or malicious
// user meets it: each reproduction of a class becomes a row, and each class
// keeps a seeded generator (tests/support/hostile_seed.hpp) that tries new
// inputs of the class every run (WEARSCALE_HOSTILE_SEED replays one).
//  - names the runner keeps for itself are refused before any work;
//  - a closed stdout or the file size limit is a write error (exit 2), never a signal;
//  - every input-driven size is bounded before it is allocated or walked;
//  - restored (checkpoint) and merged (shard summaries) state passes the
//    checks of a computed one;
//  - a result outside physics is a refusal or a failure, never exit 0;
//  - a run touches only its own output set.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <random>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "h5_fixture.hpp"
#include "hostile_seed.hpp"
#include "scratch_dir.hpp"
#include "wearscale/io/checkpoint.hpp"
#include "wearscale/io/hdf5_file.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

namespace {
const ScratchDir work_scratch("wearscale_hostile_classes_");
const fs::path work = work_scratch.path();
const std::string source = WEARSCALE_SOURCE_DIR;
const std::string pin_on_disc = source + "/cases/pin_on_disc_si_oxide.toml";
// The issue's S: a run of a second or less.
const std::string small = " --set scale.macro.grid=32 --set scale.macro.distance=0.001 --set run.fft_planning=estimate";

void write_file(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

// A fresh folder for one test (or one generated input).
fs::path folder(const std::string& name) {
  const auto dir = work / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Every entry of a folder (recursively, hidden ones too), relative.
std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> out;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    out.push_back(fs::relative(it->path(), dir).string());
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::string> partial_files(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : entries(dir))
    if (e.find(".partial-") != std::string::npos) out.push_back(e);
  return out;
}

// The pin-on-disc case with a [sweep] of the oxide thickness over `values` (a TOML array's inside).
std::string sweep_case(const std::string& values, const std::string& extra = {}) {
  return slurp(pin_on_disc) + "\n[sweep]\nkey = \"materials.layer.thickness\"\nvalues = [" + values + "]\n" + extra;
}

// A shell word: the text in single quotes.
std::string shell_word(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}
}  // namespace

// ---------------------------------------------------------------------------
// Names the runner keeps for itself, refused before any work (16 s of LAMMPS were lost to them).

struct Refusal {
  std::string name, args;
  std::vector<std::string> expected;
};
void PrintTo(const Refusal& r, std::ostream* os) { *os << r.name; }

class RefusedBeforeAnyWork : public ::testing::TestWithParam<Refusal> {};

TEST_P(RefusedBeforeAnyWork, ExitsTwoNamingTheKeyAndWritesNothing) {
  const auto& p = GetParam();
  const auto dir = folder("refused-" + p.name);
  write_file(dir / "sweep.toml", sweep_case("0, 1e-6", "table = \"run.h5\"\n"));
  const auto start = std::chrono::steady_clock::now();
  const auto r = run_cli(p.args, dir);
  EXPECT_EQ(r.status, 2) << r.err;
  for (const auto& e : p.expected) EXPECT_THAT(r.err, HasSubstr(e));
  EXPECT_THAT(r.err, Not(HasSubstr("internal error")));
  EXPECT_FALSE(fs::exists(dir / "out")) << "nothing may be written";
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30.0) << "before any work";
}

INSTANTIATE_TEST_SUITE_P(
    Issue, RefusedBeforeAnyWork,
    ::testing::Values(
        Refusal{"generate_file_run_h5",
                "surface generate --n 16 --size 1 --hurst 0.8 --kl 1 --ks 4 --hprime-rms 1 --file run.h5 --out out",
                {"key 'surface.generate.file' = \"run.h5\"", "the runner writes itself"}},
        Refusal{"generate_file_checkpoint",
                "surface generate --n 16 --size 1 --hurst 0.8 --kl 1 --ks 4 --hprime-rms 1 --file checkpoint.h5 "
                "--out out",
                {"checkpoint.h5", "the runner writes itself"}},
        Refusal{"strength_table_run_h5",
                "strength-table --backend lammps --material Si --pressures 0,10 --table run.h5 --out out",
                {"key 'output.file' = \"run.h5\"", "the runner writes itself"}},
        Refusal{"sweep_table_run_h5", "run sweep.toml --out out", {"key 'sweep.table' = \"run.h5\""}},
        Refusal{"out_empty", "run '" + pin_on_disc + "'" + small + " --out ''", {"--out '': an empty folder name"}},
        Refusal{"resume_empty", "run '" + pin_on_disc + "'" + small + " --resume ''", {"--resume '': an empty folder name"}},
        Refusal{"task_empty", "run sweep.toml --task '' --out out", {"--task '': not a shard"}},
        Refusal{"out_dash", "run '" + pin_on_disc + "'" + small + " --out -", {"--out -: wearscale writes a folder"}},
        Refusal{"tolerance_0_999999",
                "contact --set contact.grid=32 --set contact.size=1e-3 --set contact.sphere.radius=1e-2 --e-star 1e9 "
                "--pressure 1e6 --set contact.tolerance=0.999999 --out out",
                {"key 'contact.tolerance' = 0.999999: out of range; allowed: (0, 0.001]"}},
        Refusal{"junction_pressure_1e15",
                "dem junction --material SiO2 --D 20e-9 --d0 '6 nm' --slide '3 nm' --pressure 1e15 --out out",
                {"key 'dem.junction.pressure' = 1000000000000000: out of range; allowed: [0, 1.6e+10] Pa"}},
        Refusal{"rough_h_rms_1e6",
                "contact --set contact.grid=64 --set contact.size=1 --set contact.e_star=1 --set contact.mean_pressure=0.03 "
                "--set contact.rough.hurst=0.8 --set contact.rough.k_l=4 --set contact.rough.k_s=16 "
                "--set contact.rough.h_rms=1e6 --out out",
                {"key 'contact.rough.h_rms' = 1000000: out of range; allowed: (0, 1] m"}},
        Refusal{"rough_h_rms_steeper_than_100",
                "contact --set contact.grid=256 --set contact.size=1 --set contact.e_star=1 --set contact.mean_pressure=0.03 "
                "--set contact.rough.hurst=0.3 --set contact.rough.k_l=4 --set contact.rough.k_s=128 "
                "--set contact.rough.h_rms=1 --out out",
                {"key 'contact.rough.h_rms' = 1: gives an RMS slope h'_RMS = 195", "here h_rms ≤ 0.514"}}),
    [](const auto& p) { return p.param.name; });

// The class's generator: a name the runner keeps, given wherever a user names an output.
TEST(ReservedNames, GeneratedReservedOutputNamesAreRefusedBeforeAnyWork) {
  auto rng = hostile_generator("reserved-names");
  const std::vector<std::string> reserved{"run.h5", "summary.json", "checkpoint.h5", "task-1-of-2.json",
                                          "task-3-of-17.json", "log.txt"};
  for (int k = 0; k < 3; ++k) {
    const std::string name = pick(rng, reserved);
    const bool h5 = name.ends_with(".h5");
    const std::string args =
        h5 ? pick(rng, std::vector<std::string>{
                           "surface generate --n 16 --size 1 --hurst 0.8 --kl 1 --ks 4 --hprime-rms 1 --file " + name,
                           "strength-table --backend lammps --material SiO2 --pressures 0,5 --table " + name})
           : "run sweep.toml";
    SCOPED_TRACE(args);
    const auto dir = folder("reserved-" + std::to_string(k));
    write_file(dir / "sweep.toml", sweep_case("0, 1e-6", "table = \"" + name + "\"\n"));
    const auto r = run_cli(args + " --out out", dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_THAT(r.err, HasSubstr(name));
    EXPECT_FALSE(fs::exists(dir / "out"));
  }
}

// ---------------------------------------------------------------------------
// Texts handed to another program (gnuplot): data, never code. The class's generator: folder and case
// names made of gnuplot's and shells' syntax, a new set each run; no command runs and every figure is drawn.

TEST(ExternalPrograms, GeneratedGnuplotCodeInFolderAndCaseNamesRunsNothingAndEveryFigureIsDrawn) {
  auto rng = hostile_generator("gnuplot-texts");
  for (int k = 0; k < 3; ++k) {
    const auto dir = folder("gnuplot-" + std::to_string(k));
    const std::string pwned = (dir / "PWNED").string();  // where a command that ran would leave its mark
    const std::vector<std::string> parts{"'", "\"", "system('touch " + pwned + "')", "`touch " + pwned + "`",
                                         "$(touch " + pwned + ")", "\n", "\\", ";", " ", "@", "print(", ")",
                                         "µm", "x", "#", "{", "}", "\t"};
    std::string out = "o", name;
    for (int p = std::uniform_int_distribution<int>(1, 6)(rng); p > 0; --p) out += pick(rng, parts);
    for (int p = std::uniform_int_distribution<int>(1, 6)(rng); p > 0; --p) name += pick(rng, parts);
    std::replace(out.begin(), out.end(), '/', '_');  // a folder, not a path
    SCOPED_TRACE("out = " + out + ", name = " + name);
    std::string text = slurp(pin_on_disc);
    const std::string line = "name = \"pin-on-disc-si-oxide\"";
    ASSERT_NE(text.find(line), std::string::npos);
    text.replace(text.find(line), line.size(), "name = " + nlohmann::json(name).dump());  // a JSON string is TOML's
    write_file(dir / "case.toml", text);
    const auto r = run_cli("run case.toml" + small + " --out " + shell_word(out), dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_FALSE(fs::exists(pwned)) << "a text ran as a command";
    EXPECT_TRUE(fs::exists(dir / out / "friction.png"));
    EXPECT_TRUE(fs::exists(dir / out / "friction.pdf"));
  }
}

// ---------------------------------------------------------------------------
// A closed stdout and the file size limit: write errors, reported (exit 2), the unfinished files removed.

TEST(OutputSignals, TheFileSizeLimitIsAWriteErrorNotASignal) {
  const auto dir = folder("ulimit");
  const std::string cmd = "cd '" + dir.string() + "' && ulimit -f 40 && CI=true '" + std::string(WEARSCALE_CLI) +
                          "' run '" + pin_on_disc + "'" + small + " --out out >cli.stdout 2>cli.stderr";
  const int raw = std::system(("sh -c " + shell_word(cmd)).c_str());
  ASSERT_TRUE(WIFEXITED(raw)) << "killed by a signal";
  EXPECT_EQ(WEXITSTATUS(raw), 2) << slurp(dir / "cli.stderr");
  // The first file over the limit names it: one of the run's own ("... beyond this process' file size limit")
  // or gnuplot's image, which gnuplot leaves incomplete.
  EXPECT_THAT(slurp(dir / "cli.stderr"), HasSubstr("cannot write out/"));
  EXPECT_THAT(slurp(dir / "cli.stderr"), Not(HasSubstr("internal error")));
  EXPECT_THAT(partial_files(dir), ::testing::IsEmpty());
  EXPECT_FALSE(fs::exists(dir / "out" / "summary.json"));
}

TEST(OutputSignals, AClosedStandardOutputIsReportedNotASignal) {
  const auto dir = folder("closed-stdout");
  // The program's status through a pipe whose reader has gone (`| true`).
  const std::string cmd = "cd '" + dir.string() + "' && ( CI=true '" + std::string(WEARSCALE_CLI) + "' run '" +
                          pin_on_disc + "'" + small + " --out out --json 2>cli.stderr; echo $? >status ) | true";
  ASSERT_EQ(std::system(("sh -c " + shell_word(cmd)).c_str()), 0);
  const std::string status = slurp(dir / "status");
  EXPECT_EQ(status, "2\n") << slurp(dir / "cli.stderr");
  EXPECT_THAT(slurp(dir / "cli.stderr"), HasSubstr("cannot write to standard output"));
  EXPECT_TRUE(fs::exists(dir / "out" / "summary.json")) << "the run's files are complete";
}

// ---------------------------------------------------------------------------
// Every input-driven size bounded before it is allocated or walked.

TEST(Bounds, ATwentyThousandLevelTablePathIsRefusedAtOnce) {
  const auto dir = folder("deep");
  std::string path = "a";
  for (int k = 1; k < 20000; ++k) path += ".a";
  write_file(dir / "deep.toml", slurp(pin_on_disc) + "\n[scale.macro." + path + "]\nx = 1\n");
  const auto start = std::chrono::steady_clock::now();
  const auto r = run_cli("run deep.toml --out out", dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("deep.toml:"));
  EXPECT_THAT(r.err, HasSubstr("allowed:"));
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(Bounds, ASweepOfTenThousandAndOneValuesIsRefusedBeforeAnyIsPrepared) {
  const auto dir = folder("sweep-count");
  std::string values;
  for (int k = 0; k < 10001; ++k) values += (k ? ", " : "") + std::to_string(k + 1) + "e-9";
  write_file(dir / "sweep.toml", sweep_case(values));
  const auto start = std::chrono::steady_clock::now();
  const auto r = run_cli("run sweep.toml" + small + " --out out", dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("key 'sweep.values'"));
  EXPECT_THAT(r.err, HasSubstr("10001 runs (10001 values); allowed: at most 10000 runs in one sweep"));
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// 9000 values are within the bound: preparing them takes a while, and SIGTERM stops it at once.
TEST(Bounds, SigtermWhilePreparingALargeSweepStopsItWithNothingWritten) {
  const auto dir = folder("sweep-term");
  std::string values;
  for (int k = 0; k < 9000; ++k) values += (k ? ", " : "") + std::to_string(k + 1) + "e-9";
  write_file(dir / "sweep.toml", sweep_case(values));
  const std::string cmd = "cd '" + dir.string() + "' && CI=true exec '" + std::string(WEARSCALE_CLI) +
                          "' run sweep.toml" + small + " --out out >cli.stdout 2>cli.stderr";
  const pid_t pid = spawn_shell(cmd);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  const auto sent = std::chrono::steady_clock::now();
  ::kill(pid, SIGTERM);
  int status = 0;
  ::waitpid(pid, &status, 0);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
  ASSERT_TRUE(WIFEXITED(status)) << slurp(dir / "cli.stderr");
  EXPECT_EQ(WEXITSTATUS(status), 130) << slurp(dir / "cli.stderr");
  EXPECT_LT(seconds, 5.0) << "SIGTERM honoured while preparing";
  EXPECT_FALSE(fs::exists(dir / "out" / "summary.json"));
}

// An 8 × 4096 map of 1 m × 1 nm: its radial PSD would hold about 10^12 bins (20 GB before).
TEST(Bounds, ThePsdBinsOfAnElongatedTopographyAreInTheMemoryEstimate) {
  const auto dir = folder("psd-bins");
  {
    std::vector<double> h(8 * 4096);
    for (std::size_t k = 0; k < h.size(); ++k) h[k] = 1e-12 * std::sin(0.37 * static_cast<double>(k));
    h5fixture::File f(dir / "long.h5");
    f.dataset("/surface/height", {8, 4096}, h);
    f.number_attribute("/surface/height", "lx", {1.0});
    f.number_attribute("/surface/height", "ly", {1e-9});
  }
  const auto r = run_cli("surface analyze long.h5 --out out", dir, "WEARSCALE_MEMORY_LIMIT=2GiB");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("radial PSD bins"));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// The class's generator: nesting, key lengths and sweep sizes beyond their bounds.
TEST(Bounds, GeneratedOversizedCasesAreRefusedWithinSeconds) {
  auto rng = hostile_generator("bounds");
  for (int k = 0; k < 3; ++k) {
    const auto dir = folder("bounds-" + std::to_string(k));
    std::string text;
    switch (std::uniform_int_distribution<int>(0, 3)(rng)) {
      case 0: {  // a table path deeper than 32 levels
        const int depth = std::uniform_int_distribution<int>(33, 3000)(rng);
        std::string path = "t";
        for (int d = 1; d < depth; ++d) path += ".t";
        text = slurp(pin_on_disc) + "\n[scale.nano." + path + "]\nv = 1\n";
        break;
      }
      case 1: {  // arrays nested deeper than 32
        const int depth = std::uniform_int_distribution<int>(33, 200)(rng);
        text = slurp(pin_on_disc) + "\n[hostile]\nv = " + std::string(static_cast<std::size_t>(depth), '[') + "1" +
               std::string(static_cast<std::size_t>(depth), ']') + "\n";
        break;
      }
      case 2: {  // a key longer than 1024 bytes
        const int length = std::uniform_int_distribution<int>(1025, 30000)(rng);
        text = slurp(pin_on_disc) + "\n[hostile]\n" + std::string(static_cast<std::size_t>(length), 'k') + " = 1\n";
        break;
      }
      default: {  // more sweep runs than 10 000
        const int count = std::uniform_int_distribution<int>(10001, 40000)(rng);
        std::string values;
        for (int v = 0; v < count; ++v) values += (v ? "," : "") + std::to_string(v + 1) + "e-9";
        text = sweep_case(values);
      }
    }
    write_file(dir / "case.toml", text);
    const auto start = std::chrono::steady_clock::now();
    const auto r = run_cli("run case.toml" + small + " --out out", dir);
    SCOPED_TRACE(r.err.substr(0, 300));
    EXPECT_EQ(r.status, 2);
    EXPECT_THAT(r.err, HasSubstr("allowed:"));
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 15.0);
    EXPECT_FALSE(fs::exists(dir / "out"));
  }
}

// ---------------------------------------------------------------------------
// Restored state passes the checks of a computed one, whatever its checksum.

namespace {
constexpr const char* kOwner = "macro/bem-pin-on-disc";
const std::string checkpointed = " --set scale.macro.grid=32 --set scale.macro.distance=0.05 "
                                 "--set run.fft_planning=estimate --set run.checkpoint_steps=20";

// The checkpoint of a run killed mid-way (made once).
const fs::path& killed_checkpoint() {
  static const fs::path file = [] {
    const auto dir = folder("killed");
    const std::string cmd = "cd '" + dir.string() + "' && CI=true exec '" + std::string(WEARSCALE_CLI) + "' run '" +
                            pin_on_disc + "'" + checkpointed + " --out out >cli.stdout 2>cli.stderr";
    const pid_t pid = spawn_shell(cmd);
    for (int k = 0; k < 6000 && !fs::exists(dir / "out" / "checkpoint.h5"); ++k) ::usleep(5000);
    ::usleep(20000);
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_TRUE(fs::exists(dir / "out" / "checkpoint.h5")) << slurp(dir / "cli.stderr");
    return dir / "out" / "checkpoint.h5";
  }();
  return file;
}

// A copy of the killed run's checkpoint in a fresh folder with one entry changed, its checksum made anew
// (as a program that knows the format would): the bytes are intact, the state is not.
fs::path tampered(const std::string& name, const std::function<void(wearscale::CheckpointState&)>& change) {
  const auto dir = folder("tampered-" + name);
  fs::create_directories(dir / "out");
  fs::copy_file(killed_checkpoint(), dir / "out" / "checkpoint.h5");
  const std::string fingerprint =
      wearscale::H5Reader(dir / "out" / "checkpoint.h5").string_attribute_if("/", "fingerprint").value_or("");
  wearscale::Checkpointer cp(dir / "out" / "checkpoint.h5", fingerprint, {0.0, 1});  // enabled: save() writes
  cp.load();
  wearscale::CheckpointState state = *cp.restored(kOwner);
  change(state);
  cp.save(kOwner, state);
  return dir;
}

void set_entry(wearscale::CheckpointState& s, const std::string& name, std::size_t index, double value) {
  std::vector<double> a = s.array(name);
  a.at(std::min(index, a.size() - 1)) = value;
  s.put(name, a);
}

void expect_refused_resume(const fs::path& dir, const std::string& what) {
  const auto start = std::chrono::steady_clock::now();
  const auto r = run_cli("run '" + pin_on_disc + "'" + checkpointed + " --resume out", dir);
  EXPECT_EQ(r.status, 2) << what << ": " << r.err;
  EXPECT_THAT(r.err, HasSubstr("no state a run reaches")) << what;
  EXPECT_THAT(r.err, HasSubstr("checkpoint.h5")) << what;
  EXPECT_FALSE(fs::exists(dir / "out" / "summary.json")) << what;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30.0) << what;
}
}  // namespace

TEST(RestoredState, ACheckpointWithNonsenseValuesAndAValidChecksumIsRefused) {
  ASSERT_TRUE(fs::exists(killed_checkpoint()));
  struct Case {
    std::string name, entry;
    std::size_t index;
    double value;
  };
  for (const auto& c : std::vector<Case>{{"steps_1e300", "steps", 0, 1e300},
                                         {"steps_nan", "steps", 0, std::nan("")},
                                         {"pin_wear_negative", "pin_wear", 0, -1.0},
                                         {"distance_beyond_the_run", "distance", 0, 7.0},
                                         {"sample_nan", "samples/friction", 3, std::nan("")},
                                         {"sample_beyond", "samples/distance", 1000000, 7.0}}) {
    SCOPED_TRACE(c.name);
    expect_refused_resume(tampered(c.name, [&](auto& s) { set_entry(s, c.entry, c.index, c.value); }), c.name);
  }
}

// The class's generator: an entry of the state given a value outside what a run reaches.
TEST(RestoredState, GeneratedNonsenseStatesAreRefused) {
  ASSERT_TRUE(fs::exists(killed_checkpoint()));
  auto rng = hostile_generator("restored-state");
  const std::vector<std::pair<std::string, std::vector<double>>> hostile{
      {"steps", {-1.0, 0.5, 1e300, -1e300, HUGE_VAL, std::nan(""), 1e7}},
      {"solves", {-3.0, 2.5, 1e300, std::nan("")}},
      {"distance", {-1e-3, 1.0, 1e300, std::nan(""), HUGE_VAL}},
      {"pin_wear", {-1e-20, -1.0, std::nan(""), HUGE_VAL}},
      {"disc_wear", {-1e-20, std::nan(""), -HUGE_VAL}},
      {"friction_integral", {-1.0, std::nan("")}},
      {"contact_pressure", {-1.0, std::nan(""), HUGE_VAL}},
      {"pin_surface", {std::nan(""), HUGE_VAL}},
      {"samples/friction", {-0.5, std::nan(""), HUGE_VAL}},
      {"samples/pin_wear", {-1.0, std::nan("")}},
      {"samples/distance", {-1.0, 1e300}},
      {"samples/contact_fraction", {1.5, -0.1}},
      {"samples/iterations", {-1.0, 0.5, 1e300}},
      {"snapshot_counter", {-1.0, 1e300, std::nan("")}},
      {"next_step", {-1.0, 1e300, std::nan("")}}};
  for (int k = 0; k < 3; ++k) {
    const auto& [entry, values] = pick(rng, hostile);
    const double value = pick(rng, values);
    const std::size_t index = std::uniform_int_distribution<std::size_t>(0, 1000)(rng);
    const std::string what = entry + "[" + std::to_string(index) + "] = " + std::to_string(value);
    SCOPED_TRACE(what);
    expect_refused_resume(tampered("generated-" + std::to_string(k), [&](auto& s) { set_entry(s, entry, index, value); }),
                          what);
  }
}

// ---------------------------------------------------------------------------
// Merged state (a shard's summary) passes the checks of a computed result.

namespace {
const std::string shard_args = "run sweep.toml" + small + " -j 1";

fs::path two_shards(const std::string& name) {
  const auto dir = folder(name);
  write_file(dir / "sweep.toml", sweep_case("0, 1e-6"));
  for (const char* task : {"1/2", "2/2"}) {
    const auto r = run_cli(shard_args + " --task " + task + " --out shards", dir);
    EXPECT_EQ(r.status, 0) << r.err;
  }
  return dir;
}

void set_result(const fs::path& summary, const std::string& name, const nlohmann::json& value) {
  auto j = nlohmann::json::parse(slurp(summary));
  j["results"][name]["value"] = value;
  write_file(summary, j.dump(2) + "\n");
}
}  // namespace

TEST(MergedState, AShardSummaryWithAFrictionOfMinusFiveIsRefused) {
  const auto dir = two_shards("merge-mu");
  set_result(dir / "shards" / "thickness=1e-06" / "summary.json", "mu_final", -5.0);
  const auto r = run_cli("merge shards", dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("thickness=1e-06/summary.json: mu_final = -5"));
  EXPECT_THAT(r.err, HasSubstr("a friction coefficient or an RMS slope is ≥ 0"));
  EXPECT_FALSE(fs::exists(dir / "shards" / "summary.json")) << "nothing merged";
}

TEST(MergedState, GeneratedNonsenseShardResultsAreRefused) {
  auto rng = hostile_generator("merged-state");
  const auto dir = two_shards("merge-generated");
  const auto summary = dir / "shards" / "thickness=0" / "summary.json";
  const std::string intact = slurp(summary);
  const std::vector<std::pair<std::string, std::vector<nlohmann::json>>> hostile{
      {"mu_final", {-5.0, -1e-9, nullptr, "0.8"}},
      {"mu_mean", {-0.1, nullptr}},
      {"pin_wear", {-1e-12, nullptr}},
      {"disc_wear", {-1.0, "x"}},
      {"distance", {-0.001, nullptr}},
      {"p_crit_SiO2-Si", {0.0, -1e9}},
      {"mu0_SiO2-SiO2", {-0.8}}};
  for (int k = 0; k < 3; ++k) {
    const auto& [name, values] = pick(rng, hostile);
    const auto& value = pick(rng, values);
    SCOPED_TRACE(name + " = " + value.dump());
    write_file(summary, intact);
    set_result(summary, name, value);
    const auto r = run_cli("merge shards", dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_THAT(r.err, HasSubstr(name));
    EXPECT_FALSE(fs::exists(dir / "shards" / "summary.json"));
  }
  write_file(summary, intact);
  const auto r = run_cli("merge shards", dir);
  EXPECT_EQ(r.status, 0) << "the intact shards merge: " << r.err;
}

// ---------------------------------------------------------------------------
// What a case asks is what it gets.

// The docs give `thickness = "inf"` for bulk SiO2; a sweep value "inf" worked, the case's key was refused.
TEST(CaseValues, AnInfiniteLayerThicknessInTheCaseIsBulkOxide) {
  const auto dir = folder("inf-thickness");
  std::string text = slurp(pin_on_disc);
  const auto at = text.find("thickness = \"1 um\"");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, std::string("thickness = \"1 um\"").size(), "thickness = \"inf\"");
  write_file(dir / "inf.toml", text);
  auto r = run_cli("run inf.toml" + small + " --out case --json", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto from_case = nlohmann::json::parse(r.out)["results"];
  write_file(dir / "sweep.toml", sweep_case("\"inf\""));
  r = run_cli("run sweep.toml" + small + " --out sweep --json", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto from_sweep = nlohmann::json::parse(r.out)["sweep"]["runs"][0]["results"];
  for (const char* name : {"mu_final", "pin_wear", "disc_wear"}) {
    const double a = from_case[name]["value"].get<double>(), b = from_sweep[name]["value"].get<double>();
    EXPECT_NEAR(a, b, 1e-12 * std::abs(b)) << name;  // separate processes: rounding apart at most
  }
  // Bulk SiO2: the pin slides on the oxide all along, with μ0 of SiO2/SiO2 (9.13).
  EXPECT_NEAR(from_case["mu_final"]["value"].get<double>(), from_case["mu0_SiO2-SiO2"]["value"].get<double>(), 1e-12);
}

// ---------------------------------------------------------------------------
// A run touches its own output set only.

TEST(OutputSets, ResumingACompletedSingleRunWithASweepCaseIsRefusedAndDeletesNothing) {
  const auto dir = folder("resume-kind");
  auto r = run_cli("run '" + pin_on_disc + "'" + small + " --out out", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto before = entries(dir / "out");
  const std::string summary = slurp(dir / "out" / "summary.json");
  write_file(dir / "sweep.toml", sweep_case("0, 1e-6"));
  r = run_cli("run sweep.toml" + small + " --resume out", dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("is the summary of a completed single run (no [sweep]), and the case is a sweep"));
  EXPECT_EQ(entries(dir / "out"), before);
  EXPECT_EQ(slurp(dir / "out" / "summary.json"), summary);
}

TEST(OutputSets, AFreshSweepOverOtherValuesReplacesTheOldRunsInsteadOfMixingWithThem) {
  const auto dir = folder("fresh-other-values");
  write_file(dir / "a.toml", sweep_case("0, 1e-6"));
  write_file(dir / "b.toml", sweep_case("2e-6, 3e-6"));
  auto r = run_cli("run a.toml" + small + " --out out", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  r = run_cli("run b.toml" + small + " --out out", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "thickness=0"));
  EXPECT_FALSE(fs::exists(dir / "out" / "thickness=1e-06"));
  EXPECT_TRUE(fs::exists(dir / "out" / "thickness=2e-06" / "summary.json"));
  EXPECT_TRUE(fs::exists(dir / "out" / "thickness=3e-06" / "summary.json"));
  // A resume over yet other values of the completed sweep: its runs go too.
  write_file(dir / "c.toml", sweep_case("2e-6, 5e-6"));
  r = run_cli("run c.toml" + small + " --resume out", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "thickness=3e-06"));
  EXPECT_TRUE(fs::exists(dir / "out" / "thickness=5e-06" / "summary.json"));
}

// Runs no summary accounts for (a sweep killed before its summary, then another sweep into the folder): refused.
TEST(OutputSets, RunsThatNoSummaryListsAreNeverMixedWithANewSweep) {
  const auto dir = folder("foreign-runs");
  write_file(dir / "a.toml", sweep_case("0, 1e-6"));
  auto r = run_cli("run a.toml" + small + " --out out", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  fs::remove(dir / "out" / "summary.json");  // as if it had been killed before writing it
  write_file(dir / "b.toml", sweep_case("2e-6"));
  r = run_cli("run b.toml" + small + " --out out", dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("holds 2 run folder(s) that are not this run's"));
  EXPECT_THAT(r.err, HasSubstr("thickness=0"));
  EXPECT_TRUE(fs::exists(dir / "out" / "thickness=0" / "summary.json")) << "nothing removed";
  EXPECT_FALSE(fs::exists(dir / "out" / "thickness=2e-06"));
}

TEST(OutputSets, AResumedSweepLeavesNoUnfinishedFileOfTheKilledOne) {
  const auto dir = folder("partial-table");
  write_file(dir / "a.toml", sweep_case("0, 1e-6"));
  auto r = run_cli("run a.toml" + small + " --out out", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  fs::remove(dir / "out" / "summary.json");
  // What a sweep killed while it wrote its table leaves (a process id that no longer runs).
  write_file(dir / "out" / ".sweep.csv.partial-4194000", "value,mu\n0,");
  r = run_cli("run a.toml" + small + " --resume out", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(partial_files(dir / "out"), ::testing::IsEmpty());
  EXPECT_TRUE(fs::exists(dir / "out" / "summary.json"));
}

TEST(OutputSets, EachWearMapHasAFolderOfItsOwnByDefault) {
  const auto dir = folder("wearmaps");
  for (const std::string kind : {"analytic2d", "analytic3d"}) {
    const auto r = run_cli("wearmap " + kind + " --n 4 -q", dir);
    ASSERT_EQ(r.status, 0) << r.err;
  }
  for (const std::string kind : {"analytic2d", "analytic3d"}) {
    const auto summary = nlohmann::json::parse(slurp(dir / "out" / ("wearmap-" + kind) / "summary.json"));
    EXPECT_EQ(summary["study"].get<std::string>(), "wearmap/" + kind);
  }
  EXPECT_FALSE(fs::exists(dir / "out" / "wearmap"));
}

// ---------------------------------------------------------------------------
// Threads: a run at a given thread count is reproducible bit for bit (the
// difference between -j 1 and -j 2 is the order of floating-point sums, not a
// race: docs/reliability.md, "Threads").

TEST(Threads, TwoRunsOnTwoThreadsGiveTheSameFiguresBitForBit) {
  const auto dir = folder("threads");
  const std::string args = "run '" + pin_on_disc + "' --set scale.macro.grid=32 --set scale.macro.distance=0.05 "
                           "--set run.fft_planning=estimate -j 2 --json --out ";
  const auto a = run_cli(args + "a", dir);
  const auto b = run_cli(args + "b", dir);
  ASSERT_EQ(a.status, 0) << a.err;
  ASSERT_EQ(b.status, 0) << b.err;
  const auto ra = nlohmann::json::parse(a.out)["results"], rb = nlohmann::json::parse(b.out)["results"];
  for (const auto& [name, r] : ra.items()) EXPECT_EQ(r["value"], rb[name]["value"]) << name;
}
