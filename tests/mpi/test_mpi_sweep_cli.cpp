// `mpirun -np P wearscale run SWEEP`: the runs of a sweep over the ranks (the
// task farm), against the same sweep run without mpirun: every output equal
// (tables, summaries, HDF5 datasets bit for bit; fft_planning = "estimate")
// at P = 1, 3, 7 (7 > the 4 runs); a killed rank ends the job and a resume
// under another P finishes it; a run that fails is marked in the table, the
// job ends with status 1, said once. Runs mpirun itself (label "mpi").
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "mpi_launcher.hpp"
#include "oxide_sweep_case.hpp"
#include "same_outputs.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_mpi_sweep_cli_");
const fs::path work = work_scratch.path();

// The oxide-thickness sweep of the pin-on-disc case, reduced: 32² cells, a short slide, four thicknesses.
const std::string sweep_args =
    "run sweep.toml --set scale.macro.grid=32 --set scale.macro.distance=0.05 --set run.fft_planning=estimate -q";

// `wearscale args` on `ranks` ranks (0: without mpirun), one thread a rank.
CliResult run(int ranks, const std::string& args) {
  write_oxide_sweep_case(work, "0, 1e-6, 3e-6, \"inf\"");
  return run_cli(args, work, "OMP_NUM_THREADS=1", mpi_launcher(ranks));
}

// The sweep without mpirun, once for every test here.
const fs::path& serial_reference() {
  static const fs::path dir = [] {
    const auto r = run(0, sweep_args + " --out serial");
    EXPECT_EQ(r.status, 0) << r.err;
    return work / "serial";
  }();
  return dir;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}
}  // namespace

TEST(MpiSweepCli, OneThreeAndSevenRanksGiveTheSerialOutputs) {
  const auto& serial = serial_reference();
  ASSERT_TRUE(fs::exists(serial / "friction_vs_thickness.csv"));
  for (int ranks : {1, 3, 7}) {
    const std::string dir = "np" + std::to_string(ranks);
    const auto r = run(ranks, sweep_args + " --out " + dir);
    ASSERT_EQ(r.status, 0) << r.err;
    same_outputs::expect_same_outputs(serial, work / dir, same_outputs::Timings::Ignored);
    // Each run keeps its log in its folder, whichever rank ran it (the others print nothing).
    for (const auto& e : fs::directory_iterator(work / dir)) {
      if (e.is_directory() && !e.path().filename().string().starts_with(".")) {
        EXPECT_NE(slurp(e.path() / "log.txt").find("case '"), std::string::npos) << e.path() / "log.txt";
      }
    }
  }
}

TEST(MpiSweepCli, AFailedRunIsMarkedInTheTableAndTheJobEndsWithStatus1) {
  // A contact sweep over the iteration limit: 3 iterations cannot converge (a
  // numerical failure of that run alone), 200 can.
  const auto r = run(3, "contact '" WEARSCALE_SOURCE_DIR "/cases/rough_contact.toml' --set contact.grid=128 "
                        "--set contact.max_iterations=200 --set sweep.key=contact.max_iterations --set 'sweep.values=[3, 200]' -q --out failing");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(count("\n" + r.err, "\nerror: "), 1u) << r.err;  // said once, by rank 0
  EXPECT_THAT(r.err, HasSubstr("1 of 2 runs failed"));
  EXPECT_THAT(r.err, HasSubstr("no convergence"));
  EXPECT_THAT(r.err, ::testing::Not(HasSubstr("MPI_ABORT")));
  const auto table = slurp(work / "failing" / "sweep.csv");
  EXPECT_THAT(table, HasSubstr(",failed"));
  const auto summary = nlohmann::json::parse(slurp(work / "failing" / "summary.json"));
  ASSERT_EQ(summary["failed"].size(), 1u);
  EXPECT_EQ(summary["failed"][0]["run"], 1);
  EXPECT_TRUE(fs::exists(work / "failing" / "max_iterations=200" / "summary.json"));
  EXPECT_FALSE(fs::exists(work / "failing" / "max_iterations=3" / "summary.json"));
}

// A stop by SIGTERM or SIGINT to mpirun (a scheduler's time limit, Ctrl-C):
// mpirun passes it to the ranks, which stop, and a resume under another count
// finishes the sweep with the uninterrupted files.
TEST(MpiSweepCli, ASignalToMpirunStopsTheJobAndAResumeUnderAnotherCountFinishesIt) {
  // Runs of about 2 s each (the explicit integrator's fixed steps; the adaptive one is several times faster):
  // the signal, sent when the first has finished, falls while the last runs.
  const std::string args = sweep_args + " --set scale.macro.distance=1 --set scale.macro.integrator=explicit";
  ASSERT_EQ(run(0, args + " --out uninterrupted").status, 0);
  for (const int signal : {SIGTERM, SIGINT}) {
    const std::string dir = signal == SIGTERM ? "terminated" : "interrupted";
    const std::string cmd = "cd '" + work.string() + "' && exec env CI=true OMP_NUM_THREADS=1 " WEARSCALE_MPIRUN
                            " -np 3 '" + std::string(WEARSCALE_CLI) + "' " + args + " --out " + dir + " >" + dir +
                            ".out 2>" + dir + ".err";
    const pid_t job = spawn_shell(cmd);
    ASSERT_GT(job, 0);
    bool sent = false;
    for (int wait = 0; wait < 600 && !sent; ++wait) {  // once the first run has finished
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      std::error_code ec;
      for (const auto& e : fs::directory_iterator(work / dir, ec))
        if (fs::exists(e.path() / "summary.json")) sent = ::kill(job, signal) == 0;
    }
    int status = 0;
    ::waitpid(job, &status, 0);
    ASSERT_TRUE(sent) << dir;
    EXPECT_FALSE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << dir << ": the job ended as if it had finished";
    EXPECT_FALSE(fs::exists(work / dir / "summary.json")) << dir;
    const auto r = run(2, args + " --resume " + dir);
    ASSERT_EQ(r.status, 0) << dir << ": " << r.err;
    same_outputs::expect_same_outputs(work / "uninterrupted", work / dir, same_outputs::Timings::Ignored);
  }
}

TEST(MpiSweepCli, AKilledRankEndsTheJobAndAResumeUnderAnotherCountFinishesIt) {
  // Runs six times longer (about 1 s each with the explicit integrator's fixed steps), so that the kill falls
  // while runs are under way.
  const std::string args = sweep_args + " --set scale.macro.distance=0.3 --set scale.macro.integrator=explicit";
  ASSERT_EQ(run(0, args + " --out uninterrupted").status, 0);
  // Three ranks; one worker is killed (SIGKILL) once the first run has finished.
  const auto job = kill_a_worker_rank(work.string(), 3, args + " --out killed", "--out killed", [] {
    bool some_done = false;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(work / "killed", ec))
      some_done = some_done || fs::exists(e.path() / "summary.json");
    return some_done;
  });
  const bool killed = job.killed;
  const int status = job.status;
  ASSERT_TRUE(killed) << "no worker rank was found to kill";
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) != 0) << "the job went on without its rank";
  EXPECT_FALSE(fs::exists(work / "killed" / "summary.json"));
  std::size_t finished = 0;
  for (const auto& e : fs::directory_iterator(work / "killed"))
    finished += fs::exists(e.path() / "summary.json") ? 1 : 0;
  EXPECT_GE(finished, 1u);
  EXPECT_LT(finished, 4u) << "every run had finished before the kill: nothing was left to resume";
  // Resumed on two ranks: the runs that had finished are kept, the others run again.
  const auto r = run(2, args + " --resume killed");
  ASSERT_EQ(r.status, 0) << r.err;
  same_outputs::expect_same_outputs(work / "uninterrupted", work / "killed", same_outputs::Timings::Ignored);
}

// A full disk under mpirun ends the job with status 2, as without mpirun (it was 1, a "numerical" failure of
// the runs, with a summary): the disk fails at the first write of each process into the sweep's folder.
TEST(MpiSweepCli, AFullDiskEndsTheJobWithStatus2AsWithoutMpirun) {
  for (int ranks : {0, 2}) {
    const std::string dir = "full" + std::to_string(ranks);
    const std::string env = "LD_PRELOAD='" WEARSCALE_FAULT_SHIM "' FAULT_DIR='" + (work / dir).string() +
                            "' FAULT_OP=write FAULT_AT=1";
    write_oxide_sweep_case(work, "0, 1e-6, 3e-6, \"inf\"");
    const auto r = run_cli(sweep_args + " --out " + dir, work, "OMP_NUM_THREADS=1 " + env, mpi_launcher(ranks));
    EXPECT_EQ(r.status, 2) << ranks << " ranks\n" << r.err;
    EXPECT_THAT(r.err, HasSubstr("No space left on device")) << ranks << " ranks";
    EXPECT_FALSE(fs::exists(work / dir / "summary.json")) << ranks << " ranks";
  }
}
