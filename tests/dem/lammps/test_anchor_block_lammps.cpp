// The benchmark block (bench/dem/in.dem_anchor.lammps) run by LAMMPS and by
// wearscale: the same linear spring-dashpot law with history must give the
// same trajectory, measured by the kinetic energies LAMMPS prints.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

#include "wearscale/dem/anchor_block.hpp"
#include "scratch_dir.hpp"

using namespace wearscale::dem;
namespace fs = std::filesystem;

TEST(AnchorBlockAgainstLammps, KineticEnergiesAgreeAfterFiveHundredSteps) {
  if (std::system("command -v lmp >/dev/null 2>&1") != 0) GTEST_SKIP() << "lmp not installed";
  static const ScratchDir dir_scratch("wearscale-anchor-");
  const std::filesystem::path dir = dir_scratch.path();
  fs::create_directories(dir);
  const std::string deck = std::string(WEARSCALE_BENCH_DECKS) + "/in.dem_anchor.lammps";
  const std::string cmd = "cd '" + dir.string() + "' && lmp -in '" + deck +
                          "' -var n 8 -var nsteps 500 -log log.lammps -screen none";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  // Thermo lines: "Step Atoms KinEng c_rke".
  std::ifstream log(dir / "log.lammps");
  std::string line;
  double ke = -1.0, rke = -1.0;
  bool table = false;
  while (std::getline(log, line)) {
    if (line.find("Step Atoms KinEng c_rke") != std::string::npos) {
      table = true;
      continue;
    }
    if (!table) continue;
    std::istringstream in(line);
    long step = 0, atoms = 0;
    double k = 0, kr = 0;
    if (in >> step >> atoms >> k >> kr && step == 500) {
      ke = k;
      rke = kr;
    }
  }
  fs::remove_all(dir);
  ASSERT_GT(ke, 0.0) << "no thermo line for step 500 in the LAMMPS log";

  auto sim = make_anchor_block({8, 10});
  sim.run(500);
  const auto& p = sim.particles();
  double translational = 0.0, rotational = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    translational += 0.5 * p.mass[i] * dot(p.velocity[i], p.velocity[i]);
    rotational += 0.5 / p.inv_inertia[i] * dot(p.omega[i], p.omega[i]);
  }
  // Same arithmetic up to summation order; LAMMPS prints 8 digits.
  EXPECT_NEAR(translational, ke, 1e-6 * ke);
  EXPECT_NEAR(rotational, rke, 1e-5 * rke);
}
