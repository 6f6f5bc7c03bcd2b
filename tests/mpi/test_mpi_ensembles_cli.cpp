// The ensembles inside one run over the ranks of `mpirun -np P` (the task
// farm), against the same command without mpirun: every output equal (tables
// byte for byte, HDF5 datasets bit for bit, plots), wall times aside, at
// P = 1, 3, 7 (7 > the tasks); a job whose worker rank is killed resumes
// under another P with the tasks it had finished. Runs mpirun itself (label "mpi").
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "mpi_launcher.hpp"
#include "same_outputs.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;

namespace {
const ScratchDir work_scratch("wearscale_mpi_ensembles_cli_");
const fs::path work = work_scratch.path();

// `wearscale args` on `ranks` ranks (0: without mpirun), one thread a rank.
CliResult run(int ranks, const std::string& args) {
  return run_cli(args, work, "OMP_NUM_THREADS=1", mpi_launcher(ranks));
}
}  // namespace

// The rough wear map of Fig. 5.6 reduced: 64² surfaces, two seeds (the farm's
// tasks), 4 × 4 pixels; its flags (--n, --seeds) count under mpirun as without.
TEST(MpiEnsemblesCli, TheRoughWearMapsSurfacesOverOneThreeAndSevenRanksGiveTheSerialMap) {
  const std::string args = "wearmap rough --n 64 --seeds 2 --n-loads 4 --n-dstar 4 -q";
  const auto serial = run(0, args + " --out wearmap_serial");
  ASSERT_EQ(serial.status, 0) << serial.err;
  for (int ranks : {1, 3, 7}) {
    const std::string dir = "wearmap_np" + std::to_string(ranks);
    const auto r = run(ranks, args + " --out " + dir);
    ASSERT_EQ(r.status, 0) << r.err;
    same_outputs::expect_same_outputs(work / "wearmap_serial", work / dir, same_outputs::Timings::Ignored);
    if (ranks == 1) continue;
    // The summary says which rank ran each surface, on how many threads, for how long.
    const auto summary = nlohmann::json::parse(slurp(work / dir / "summary.json"));
    ASSERT_TRUE(summary.contains("tasks")) << summary.dump(2);
    const auto& tasks = summary["tasks"];
    ASSERT_EQ(tasks.size(), 2u);
    for (std::size_t s = 0; s < 2; ++s) {
      EXPECT_EQ(tasks[s]["seed"].get<int>(), static_cast<int>(s + 1));
      EXPECT_GE(tasks[s]["rank"].get<int>(), 0);
      EXPECT_LT(tasks[s]["rank"].get<int>(), ranks);
      EXPECT_EQ(tasks[s]["threads"].get<int>(), 1);
      EXPECT_GT(tasks[s]["seconds"].get<double>(), 0.0);
    }
  }
}

// A worker rank killed (SIGKILL) while the map's surfaces are under way ends
// the job; the surfaces finished by then are kept (tasks/), and the job
// resumed on two ranks computes only the others: the serial map.
TEST(MpiEnsemblesCli, AWearMapWhoseRankIsKilledResumesUnderAnotherCountWithTheSurfacesItHadFinished) {
  const std::string args = "wearmap rough --n 128 --seeds 6 --n-loads 6 --n-dstar 4";
  ASSERT_EQ(run(0, args + " -q --out wearmap_uninterrupted").status, 0);
  const auto kept = [] {
    std::size_t n = 0;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(work / "wearmap_killed" / "tasks", ec))
      n += e.path().extension() == ".task" ? 1 : 0;
    return n;
  };
  const auto job = kill_a_worker_rank(work.string(), 3, args + " -q --out wearmap_killed", "--out wearmap_killed",
                                      [&] { return kept() >= 1; });
  ASSERT_TRUE(job.killed) << "no worker rank was found to kill";
  EXPECT_TRUE(WIFEXITED(job.status) && WEXITSTATUS(job.status) != 0) << "the job went on without its rank";
  EXPECT_FALSE(fs::exists(work / "wearmap_killed" / "summary.json"));
  const std::size_t finished = kept();
  EXPECT_GE(finished, 1u);
  ASSERT_LT(finished, 6u) << "every surface had finished before the kill: nothing was left to resume";
  const auto r = run(2, args + " --resume wearmap_killed");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find(std::to_string(finished) + " of 6 tasks taken from"), std::string::npos) << r.err;
  same_outputs::expect_same_outputs(work / "wearmap_uninterrupted", work / "wearmap_killed",
                                    same_outputs::Timings::Ignored);
}

// Fig. 7.2's junction runs (nano/dem in a pipeline) reduced: a 12 × 6 cell,
// two sizes D/L at two pressures (the farm's tasks), a short slide, no cache;
// rank 0 runs the pipeline, the others serve its junction runs.
TEST(MpiEnsemblesCli, TheJunctionRunsOfNanoDemOverOneThreeAndSevenRanksGiveTheSerialLaw) {
  const std::string args = "run '" WEARSCALE_SOURCE_DIR "/cases/junction_sio2.toml' --set scale.nano.length=12 "
                           "--set scale.nano.height=6 --set scale.nano.cache=false --set 'scale.nano.contact_ratios=[0.5, 1]' "
                           "--set 'scale.nano.pressures=[1e9, 4e9]' --set scale.nano.sliding_distance=0.2 -q";
  const auto serial = run(0, args + " --out junction_serial");
  ASSERT_EQ(serial.status, 0) << serial.err;
  for (int ranks : {1, 3, 7}) {
    const std::string dir = "junction_np" + std::to_string(ranks);
    const auto r = run(ranks, args + " --out " + dir);
    ASSERT_EQ(r.status, 0) << r.err;
    same_outputs::expect_same_outputs(work / "junction_serial", work / dir, same_outputs::Timings::Ignored);
    if (ranks == 1) continue;
    const auto summary = nlohmann::json::parse(slurp(work / dir / "summary.json"));
    ASSERT_TRUE(summary.contains("tasks")) << summary.dump(2);
    ASSERT_EQ(summary["tasks"].size(), 4u);
    for (const auto& t : summary["tasks"]) {
      EXPECT_LT(t["rank"].get<int>(), ranks);
      EXPECT_GT(t["seconds"].get<double>(), 0.0);
    }
  }
}

// A pipeline on live LAMMPS strengths (molecular/lammps, Si, two pressures of a
// short shear test): rank 0 runs the pipeline, the other ranks serve its
// LAMMPS runs; the headline figures equal the serial ones, and each run ran
// once (one cache entry per pressure).
TEST(MpiEnsemblesCli, TheLammpsRunsOfAMolecularScaleOverThreeRanksGiveTheSerialStrengths) {
  if (std::system("command -v lmp >/dev/null 2>&1") != 0) GTEST_SKIP() << "no lmp on PATH (apt-get install lammps)";
  fs::create_directories(work);
  std::ofstream(work / "lammps_si.toml") << "[case]\nname = \"lammps-si\"\n[materials]\npin = \"Si\"\ndisc = \"Si\"\n"
                                            "[scale.molecular]\nbackend = \"lammps\"\npressures = [0, 5e9]\n"
                                            "strain_end = 0.02\nwindow = [0.01, 0.02]\ncompression_time = 0\n"
                                            "sample_steps = 20\n[scale.nano]\nbackend = \"analytic\"\n";
  const auto serial = run(0, "run lammps_si.toml -q --set scale.molecular.cache_dir=cache_serial --out lammps_serial");
  ASSERT_EQ(serial.status, 0) << serial.err;
  const auto r = run(3, "run lammps_si.toml -q --set scale.molecular.cache_dir=cache_np3 --out lammps_np3");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto a = nlohmann::json::parse(slurp(work / "lammps_serial" / "summary.json"))["results"];
  const auto b = nlohmann::json::parse(slurp(work / "lammps_np3" / "summary.json"))["results"];
  ASSERT_FALSE(a.empty());
  for (const auto& [name, v] : a.items()) EXPECT_EQ(v["value"], b[name]["value"]) << name;
  // One shear run per pressure, and the elastic check of the material: its sample as built and the ideal
  // lattice it is compared with.
  std::size_t shear_runs = 0, elastic_runs = 0;
  for (const auto& e : fs::directory_iterator(work / "cache_np3")) {
    if (!e.is_directory() || e.path().filename().string().size() != 64) continue;
    shear_runs += fs::exists(e.path() / "shear.dat") ? 1 : 0;
    elastic_runs += fs::exists(e.path() / "elastic.txt") ? 1 : 0;
  }
  EXPECT_EQ(shear_runs, 2u) << "one LAMMPS shear run per pressure";
  EXPECT_EQ(elastic_runs, 2u) << "the elastic check: the sample and the ideal lattice, once";
}
