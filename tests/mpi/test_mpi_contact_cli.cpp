// `mpirun -np P wearscale contact`: the fields in slabs over the ranks, the
// serial study's answer and files; what is not distributed is refused (status
// 2, the key named, nothing written). Runs mpirun itself (label "mpi").
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_mpi_contact_cli_");
const fs::path work = work_scratch.path();
const std::string rough_case = "'" + std::string(WEARSCALE_SOURCE_DIR) + "/cases/rough_contact.toml'";

// `wearscale args` on `ranks` ranks (0: without mpirun).
CliResult run(int ranks, const std::string& args) {
  fs::create_directories(work);
  const auto out = work / "cli.stdout", err = work / "cli.stderr";
  const std::string launcher =
      ranks == 0 ? std::string() : std::string(WEARSCALE_MPIRUN) + " -np " + std::to_string(ranks) + " ";
  const std::string cmd = "cd '" + work.string() + "' && CI=true OMP_NUM_THREADS=1 " + launcher + "'" +
                          std::string(WEARSCALE_CLI) + "' " + args + " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int raw = std::system(cmd.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
}

void expect_same_results(const nlohmann::json& serial, const nlohmann::json& slab, int ranks) {
  ASSERT_EQ(serial["results"].size(), slab["results"].size());
  for (const auto& [name, v] : serial["results"].items()) {
    if (name == "error") continue;  // the residual at convergence, not a result: below the tolerance in both
    const double a = v["value"].get<double>(), b = slab["results"][name]["value"].get<double>();
    EXPECT_LE(std::abs(a - b), 1e-12 * std::max(std::abs(a), 1e-300)) << name << " at P = " << ranks;
  }
  EXPECT_LT(slab["results"]["error"]["value"].get<double>(), 1e-10);
  EXPECT_EQ(serial["results"]["iterations"], slab["results"]["iterations"]);
  EXPECT_EQ(serial["results"]["clusters"], slab["results"]["clusters"]);
}
}  // namespace

TEST(MpiContactCli, TwoAndThreeRanksGiveTheSerialSummaryAndFiles) {
  const std::string args = "contact " + rough_case + " --set contact.grid=128 --json -q";
  const auto serial = run(0, args + " --out serial");
  ASSERT_EQ(serial.status, 0) << serial.err;
  const auto s = nlohmann::json::parse(serial.out);
  for (int ranks : {2, 3}) {
    const std::string dir = "slab" + std::to_string(ranks);
    const auto slab = run(ranks, args + " --out " + dir);
    ASSERT_EQ(slab.status, 0) << slab.err;
    expect_same_results(s, nlohmann::json::parse(slab.out), ranks);
    for (const char* f : {"contact.h5", "contact.xdmf", "clusters.csv", "summary.json"})
      EXPECT_TRUE(fs::exists(work / dir / f)) << f;
  }
}

TEST(MpiContactCli, ASphereOnARoughSurfaceGivesTheSerialSummary) {
  const std::string args = "contact " + rough_case +
                           " --set contact.grid=160 --set contact.sphere.radius=2 --set contact.rough.hprime_rms=0.2 "
                           "--set contact.mean_pressure=0.01 --json -q";
  const auto serial = run(0, args + " --out sphere_serial");
  ASSERT_EQ(serial.status, 0) << serial.err;
  const auto slab = run(2, args + " --out sphere_slab");
  ASSERT_EQ(slab.status, 0) << slab.err;
  expect_same_results(nlohmann::json::parse(serial.out), nlohmann::json::parse(slab.out), 2);
}

TEST(MpiContactCli, WhatIsNotDistributedIsRefusedNamingTheKey) {
  const std::string args = "contact " + rough_case + " --set contact.grid=64 -q";
  const std::pair<const char*, const char*> cases[] = {
      {"--set contact.boundary=free", "contact.boundary"},
      {"--set contact.friction=coulomb --set contact.poisson=0.3 --set contact.friction_coefficient=0.5",
       "contact.friction"},
      {"--set contact.surface=rough.h5", "contact.surface"}};
  for (const auto& [set, key] : cases) {
    const std::string dir = std::string("refused_") + std::to_string(std::hash<std::string>{}(key) % 1000);
    const auto r = run(2, args + " " + set + " --out " + dir);
    EXPECT_EQ(r.status, 2) << set << "\n" << r.err;
    EXPECT_THAT(r.err, HasSubstr(key)) << set;
    EXPECT_FALSE(fs::exists(work / dir / "summary.json")) << set;
    EXPECT_FALSE(fs::exists(work / dir / "contact.h5")) << set;
  }
}
