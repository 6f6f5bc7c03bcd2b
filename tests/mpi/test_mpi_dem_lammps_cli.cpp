// `wearscale dem STUDY … --set dem.engine=lammps`: every DEM study on the
// LAMMPS engine without mpirun and as one run over three ranks (LAMMPS'
// domain decomposition; rank 0 alone prints and writes); a run of each study
// on two ranks whose worker rank is killed resumes to the outputs of the
// uninterrupted one bit for bit; nano/dem's junction runs on the LAMMPS
// engine over the task farm give the serial law. Reduced cases (seconds
// each); label "mpi".
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "reduced_dem_studies.hpp"
#include "cli_runner.hpp"
#include "mpi_launcher.hpp"
#include "same_outputs.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_mpi_dem_lammps_cli_");
const fs::path work = work_scratch.path();

CliResult run(int ranks, const std::string& args) {
  return run_cli(args, work, "OMP_NUM_THREADS=1", mpi_launcher(ranks));
}

using DemStudy = wearscale::test_support::ReducedDemStudy;
const auto& dem_studies = wearscale::test_support::reduced_dem_studies;
const std::string on_lammps = " --set dem.engine=lammps";

nlohmann::json results_of(const fs::path& summary) { return nlohmann::json::parse(slurp(summary))["results"]; }

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}
}  // namespace

class MpiDemLammpsCli : public ::testing::TestWithParam<DemStudy> {};

// The same figures are reported, the counts exactly (the sample is built on
// rank 0 alike), every value finite; the files are there. (The trajectories
// of one and three ranks add forces in other orders: chaotic runs agree in
// their aggregates, tests/mpi/mpi_dem_lammps.cpp.)
TEST_P(MpiDemLammpsCli, RunsWithoutMpirunAndAsOneRunOverThreeRanks) {
  const DemStudy& study = GetParam();
  const std::string args = "-j 1 " + study.args + on_lammps;
  const auto serial = run(0, args + " --out " + study.label + "_serial");
  ASSERT_EQ(serial.status, 0) << serial.err;
  const auto three = run(3, args + " --out " + study.label + "_np3");
  ASSERT_EQ(three.status, 0) << three.err;
  EXPECT_THAT(three.err, HasSubstr("on 3 MPI ranks"));
  EXPECT_EQ(count(three.out, "wrote "), count(serial.out, "wrote ")) << "rank 0 alone writes: " << three.out;
  const auto a = results_of(work / (study.label + "_serial") / "summary.json");
  const auto b = results_of(work / (study.label + "_np3") / "summary.json");
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [name, r] : a.items()) {
    ASSERT_TRUE(b.contains(name)) << name;
    EXPECT_TRUE(std::isfinite(b[name]["value"].get<double>())) << name;
    if (name == "particles" || name == "steps") {
      EXPECT_EQ(b[name]["value"].get<double>(), r["value"].get<double>()) << name;
    }
  }
  if (!study.dump.empty()) {
    EXPECT_GT(fs::file_size(work / (study.label + "_np3") / study.dump), 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(EveryStudy, MpiDemLammpsCli, ::testing::ValuesIn(dem_studies),
                         [](const ::testing::TestParamInfo<DemStudy>& p) { return p.param.label; });

// A worker rank killed (SIGKILL) after the first checkpoint ends the job; the
// run resumed on two ranks ends with the outputs of the uninterrupted run on
// two ranks, results, history and snapshots bit for bit: every study.
TEST(MpiDemLammpsResume, AKilledRunOnTwoRanksResumesBitForBit) {
  for (const auto& study : dem_studies) {
    SCOPED_TRACE(study.label);
    const std::string args = "-j 1 " + study.args + on_lammps + " --set run.checkpoint_steps=200";
    const std::string reference = study.label + "_np2_reference", part = study.label + "_np2_part";
    const auto r = run(2, args + " --out " + reference);
    ASSERT_EQ(r.status, 0) << r.err;
    const auto killed = kill_a_worker_rank(work.string(), 2, args + " --out " + part, part,
                                           [&] { return fs::exists(work / part / "checkpoint.h5"); });
    ASSERT_TRUE(killed.killed) << study.label << ": " << slurp(work / "killed.err");
    const auto resumed = run(2, args + " --resume " + part);
    ASSERT_EQ(resumed.status, 0) << resumed.err;
    EXPECT_THAT(resumed.err, HasSubstr("resumes at step"));
    EXPECT_EQ(results_of(work / part / "summary.json"), results_of(work / reference / "summary.json")) << study.label;
    if (!study.dump.empty()) {
      EXPECT_EQ(slurp(work / part / (study.name + "_history.csv")), slurp(work / reference / (study.name + "_history.csv")));
      EXPECT_TRUE(slurp(work / part / study.dump) == slurp(work / reference / study.dump)) << "the snapshots differ";
    }
    EXPECT_FALSE(fs::exists(work / part / "checkpoint.h5")) << "a completed run keeps no checkpoint";
  }
}

// Fig. 7.2's junction runs (nano/dem, reduced as in test_mpi_ensembles_cli)
// on the LAMMPS engine: each run a LAMMPS instance of its own, on the rank
// the farm hands it to (ranks 1 and 2: rank 0 hands them out), the same bits
// as without mpirun.
TEST(MpiDemLammpsCli, TheJunctionRunsOfNanoDemOnTheLammpsEngineOverThreeRanksGiveTheSerialLaw) {
  const std::string args = "run '" WEARSCALE_SOURCE_DIR "/cases/junction_sio2.toml' --set scale.nano.length=12 "
                           "--set scale.nano.height=6 --set scale.nano.cache=false --set 'scale.nano.contact_ratios=[0.5, 1]' "
                           "--set 'scale.nano.pressures=[1e9, 4e9]' --set scale.nano.sliding_distance=0.2 "
                           "--set scale.nano.engine=lammps -q";
  const auto serial = run(0, args + " --out nano_serial");
  ASSERT_EQ(serial.status, 0) << serial.err;
  const auto three = run(3, args + " --out nano_np3");
  ASSERT_EQ(three.status, 0) << three.err;
  same_outputs::expect_same_outputs(work / "nano_serial", work / "nano_np3", same_outputs::Timings::Ignored);
  const auto summary = nlohmann::json::parse(slurp(work / "nano_np3" / "summary.json"));
  ASSERT_TRUE(summary.contains("tasks")) << summary.dump(2);
  for (const auto& t : summary["tasks"]) EXPECT_NE(t["rank"].get<int>(), 0) << "rank 0 hands out LAMMPS runs only";
}
