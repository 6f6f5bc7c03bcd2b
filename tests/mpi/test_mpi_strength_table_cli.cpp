// `mpirun -np P wearscale strength-table --backend lammps`: the pressure
// points over the ranks (the task farm), each point's lmp on `--ranks 2` of
// its own (a nested `mpirun -np 2 lmp`, launched from a rank), after the
// sample's elastic check (one task), against the
// same table without mpirun: the same table, the same strengths; a rerun on
// the same cache runs nothing. And the result cache across ranks: the runs of
// a sweep that all ask for the same LAMMPS runs at once run each once (one
// writer per entry), every run reading the same strengths. A failed point
// ends every rank with status 1, said once by rank 0. Runs mpirun and lmp
// itself (label "mpi": gtest_discover_tests takes one label here).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "mpi_launcher.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;

namespace {
const ScratchDir work_scratch("wearscale_mpi_strength_table_");
const fs::path work = work_scratch.path();

// Two points of the Si smoke preset, cut to a strain of 0.02 (about 400 steps): seconds each.
const std::string table_args =
    "strength-table --backend lammps --material Si --pressures 0,5 --ranks 2 --set md.strain_end=0.02 "
    "--set 'md.window=[0.01, 0.02]' --set md.compression_time=0 --set md.sample_steps=20 -q";

// `wearscale args` on `ranks` ranks (0: without mpirun), one thread a rank, the LAMMPS cache in `cache`.
CliResult run(int ranks, const std::string& args, const std::string& cache) {
  return run_cli(args, work, "OMP_NUM_THREADS=1 WEARSCALE_CACHE='" + (work / cache).string() + "'", mpi_launcher(ranks));
}

nlohmann::json summary(const std::string& dir) { return nlohmann::json::parse(slurp(work / dir / "summary.json")); }

// What a table's run says of its points, less their cost (wall time, cached or not).
nlohmann::json figures(const std::string& dir) {
  nlohmann::json rows = summary(dir).at("rows");
  for (auto& r : rows) {
    r.erase("wall_seconds");
    r.erase("cached");
  }
  return {{"results", summary(dir).at("results")}, {"rows", rows}};
}

// The shear curve a fake lmp writes (peak 12 GPa at strain 0.3, 2 GPa after),
// as a file it copies: a shell loop forks per line, seconds on a loaded machine.
fs::path fake_curve() {
  const fs::path file = work / "fake-shear.dat";
  if (fs::exists(file)) return file;
  fs::create_directories(work);
  std::ofstream out(file);
  out << "# Time-averaged data for fix curve\n# TimeStep v_strain v_tau v_p_n v_h c_t_mobile\n";
  for (int i = 1; i <= 60; ++i)
    out << 2000 + 100 * i << " 0." << (i < 10 ? "0" : "") << i << " " << (i <= 30 ? i * 4 / 10 : 2) << " 0 19 300\n";
  return file;
}

// The rows of an elastic-constants deck (md/elastic_constants.hpp) for an
// isotropic solid of E = 120 GPa, ν = 0.22 (the published reference of the
// built-in SiO2, so that a crystal's and an amorphous sample's checks pass):
// C11 = 137.0, C12 = 38.6, C44 = 49.2 GPa, strains ±1e-3, pressures in bar.
fs::path fake_elastic_rows() {
  const fs::path file = work / "fake-elastic.txt";
  if (fs::exists(file)) return file;
  fs::create_directories(work);
  const double c11 = 137.0, c12 = 38.6, c44 = 49.2;
  const double c[6][6] = {{c11, c12, c12, 0, 0, 0}, {c12, c11, c12, 0, 0, 0}, {c12, c12, c11, 0, 0, 0},
                          {0, 0, 0, c44, 0, 0},     {0, 0, 0, 0, c44, 0},     {0, 0, 0, 0, 0, c44}};
  std::ofstream out(file);
  out << "0 0 0 0 0 0 0 0 0 16.293 16.293 16.293\n";
  int k = 1;
  for (int j = 0; j < 6; ++j)
    for (int sign : {1, -1}) {
      out << k++ << " " << j + 1 << " " << sign;
      for (int i = 0; i < 6; ++i) out << " " << -sign * 1e-3 * c[i][j] * 1e4;
      out << " 16.293 16.293 16.293\n";
    }
  return file;
}

// A fake lmp at `file`: it answers `lmp -h` with a LAMMPS version line, an
// elastic-constants deck with the rows above, and otherwise runs `body`
// (shell) in the run folder.
void write_fake_lmp(const fs::path& file, const std::string& body, bool elastic = true) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << "#!/bin/sh\n"
                         "if [ \"$1\" = \"-h\" ]; then echo 'Large-scale Atomic/Molecular Massively Parallel "
                         "Simulator - 1 Jan 2000 - fake'; exit 0; fi\n"
                      << (elastic ? "if grep -q elastic.txt in.lammps; then cp '" + fake_elastic_rows().string() +
                                        "' elastic.txt; printf 'atoms 216\\ncompleted yes\\n' > sample.txt; exit 0; "
                                        "fi\n"
                                  : std::string())
                      << body;
  fs::permissions(file, fs::perms::owner_all);
}

// Every finished shear run of a LAMMPS cache (the elastic check's two runs,
// which write no shear curve, are entries of their own beside them).
std::vector<fs::path> entries(const std::string& cache) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(work / cache / "lammps"))
    if (fs::exists(e.path() / "COMPLETE") && fs::exists(e.path() / "shear.dat")) out.push_back(e.path());
  return out;
}
}  // namespace

TEST(MpiStrengthTableCli, PointsOverThreeRanksEqualTheSerialTableWithLammpsOnTwoRanksEach) {
  if (std::system("command -v lmp >/dev/null 2>&1") != 0) GTEST_SKIP() << "no lmp on PATH (apt-get install lammps)";
  const auto serial = run(0, table_args + " --out serial", "cache-serial");
  ASSERT_EQ(serial.status, 0) << serial.err;
  // A cache of its own: every point really runs, `mpirun -np 2 lmp` launched from a rank of this job.
  const auto farmed = run(3, table_args + " --out np3", "cache-np3");
  ASSERT_EQ(farmed.status, 0) << farmed.err;
  EXPECT_EQ(slurp(work / "np3/lammps_smoke_Si.csv"), slurp(work / "serial/lammps_smoke_Si.csv"));
  EXPECT_EQ(figures("np3"), figures("serial"));
  const auto ran = entries("cache-np3");
  ASSERT_EQ(ran.size(), 2u) << "one entry per pressure";
  for (const auto& e : ran) {
    EXPECT_NE(slurp(e / "cost.txt").find("ranks 2"), std::string::npos) << e;
    EXPECT_NE(slurp(e / "log.lammps").find("on 2 procs"), std::string::npos) << e << ": lmp did not run on 2 ranks";
  }
  for (const auto& row : summary("np3").at("rows")) EXPECT_FALSE(row.at("cached").get<bool>());
  // Again on the same cache, on one rank of an MPI job: nothing runs, the same table.
  const auto again = run(1, table_args + " --out np1", "cache-np3");
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(slurp(work / "np1/lammps_smoke_Si.csv"), slurp(work / "serial/lammps_smoke_Si.csv"));
  for (const auto& row : summary("np1").at("rows")) EXPECT_TRUE(row.at("cached").get<bool>());
}

TEST(MpiStrengthTableCli, RanksAskingForTheSameRunsAtOnceRunEachOnce) {
  // A fake lmp (a second a run) that counts its runs and writes a shear curve
  // peaking at 12 GPa; three runs of a sweep that differ only in the path of
  // lmp (three links to it: not an input of a run's cache key) ask for the
  // same two pressure points on three ranks at once.
  const fs::path fake = work / "slow-lmp", counter = work / "lmp-calls.txt";
  write_fake_lmp(fake, "echo run >> '" + counter.string() + "'\nsleep 1\n"
                       "cp '" + fake_curve().string() + "' shear.dat\n"
                       "printf 'atoms 544\\nlx_A 21.724\\nly_A 21.724\\nh0_A 19.0\\nh_gap_A 15.0\\ncompleted yes\\n' > "
                       "sample.txt\n");
  std::string links;
  for (const char* name : {"lmp-a", "lmp-b", "lmp-c"}) {
    fs::remove(work / name);
    fs::create_symlink(fake, work / name);
    links += std::string(links.empty() ? "" : ", ") + "\"" + (work / name).string() + "\"";
  }
  std::ofstream(work / "sweep.toml") << "[case]\nstudy = \"strength-table\"\n[md]\nmaterial = \"Si\"\n"
                                        "pressures = [\"0 GPa\", \"10 GPa\"]\nlmp = \"" << (work / "lmp-a").string()
                                     << "\"\n[output]\nfile = \"si.csv\"\n"
                                        "[sweep]\nkey = \"md.lmp\"\nvalues = [" << links << "]\n";
  const auto r = run(3, "run sweep.toml -q --out shared", "cache-shared");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string calls = slurp(counter);
  EXPECT_EQ(std::count(calls.begin(), calls.end(), '\n'), 2) << "each of the two pressures ran once";
  EXPECT_EQ(entries("cache-shared").size(), 2u);
  for (const auto& e : fs::directory_iterator(work / "cache-shared" / "lammps"))
    EXPECT_EQ(e.path().filename().string().find(".partial-"), std::string::npos) << e.path();
  std::vector<std::string> tables;
  for (const auto& e : fs::recursive_directory_iterator(work / "shared"))
    if (e.path().filename() == "si.csv") tables.push_back(slurp(e.path()));
  ASSERT_EQ(tables.size(), 3u) << "one si.csv per run";
  for (const auto& t : tables) EXPECT_EQ(t, tables.front());
  EXPECT_NE(tables.front().find("1.2e+10"), std::string::npos) << "the curve's 12 GPa peak:\n" << tables.front();
}

TEST(MpiStrengthTableCli, AFailedPointEndsEveryRankWithStatus1NamingIt) {
  // A fake lmp that fails every run with a LAMMPS error line.
  const fs::path fake = work / "failing-lmp";
  // (The elastic check's runs are the first to fail: the study stops there.)
  write_fake_lmp(fake, "echo 'ERROR: Lost atoms (fake)'; exit 1\n", false);
  const auto r = run(3, "strength-table --backend lammps --material Si --pressures 0,5 -q --lmp '" + fake.string() +
                            "' --out failed",
                     "cache-failed");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("1 of 1 LAMMPS runs failed"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("Si elastic constants"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ERROR: Lost atoms (fake)"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("error:"), r.err.rfind("error:")) << "said once, by rank 0:\n" << r.err;
  EXPECT_FALSE(fs::exists(work / "failed" / "lammps_smoke_Si.csv"));
}

TEST(MpiStrengthTableCli, SiO2QuenchRunsOnceBeforeItsPointsOverTheRanks) {
  // A fake lmp: the melt-quench deck (it ends with write_data) writes a
  // quenched sample, a shear deck (it reads that sample, copied into its
  // folder) writes a curve; each run counted.
  const fs::path fake = work / "sio2-lmp", counter = work / "sio2-calls.txt";
  write_fake_lmp(fake, "if grep -q '^write_data' in.lammps; then\n"
                       "  echo quench >> '" + counter.string() + "'\n"
                       "  echo 'fake sample' > quenched.data\n"
                       "  printf 'atoms 1536\\ndensity_g_cm3 2.2\\nlx_A 28\\nlz_A 28\\ncompleted yes\\n' > sample.txt\n"
                       "  exit 0\n"
                       "fi\n"
                       "[ -f quenched.data ] || { echo 'ERROR: no quenched sample (fake)'; exit 1; }\n"
                       "echo shear >> '" + counter.string() + "'\n"
                       "cp '" + fake_curve().string() + "' shear.dat\n"
                       "printf 'atoms 1536\\nlx_A 28\\nly_A 28\\nh0_A 25\\nh_gap_A 21\\ncompleted yes\\n' > sample.txt\n");
  const std::string args = "strength-table --backend lammps --material SiO2 --pressures 0,5,10 --ranks 1 -q --lmp '" +
                           fake.string() + "'";
  const auto serial = run(0, args + " --out sio2-serial", "cache-sio2-serial");
  ASSERT_EQ(serial.status, 0) << serial.err;
  fs::remove(counter);
  const auto farmed = run(3, args + " --out sio2-np3", "cache-sio2-np3");
  ASSERT_EQ(farmed.status, 0) << farmed.err;
  EXPECT_EQ(slurp(counter), "quench\nshear\nshear\nshear\n") << "the quench once, first";
  EXPECT_EQ(slurp(work / "sio2-np3/lammps_smoke_SiO2.csv"), slurp(work / "sio2-serial/lammps_smoke_SiO2.csv"));
  EXPECT_EQ(figures("sio2-np3"), figures("sio2-serial"));
}
