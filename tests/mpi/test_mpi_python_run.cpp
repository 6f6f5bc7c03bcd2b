// `mpirun -np P python3 script.py` where the script calls wearscale.run() on
// a sweep case: the module owns MPI (no mpi4py), the runs are farmed over the
// ranks and rank 0 writes; the outputs equal those of the same script run
// without mpirun (tables, summaries, HDF5 datasets bit for bit; fft_planning
// = "estimate") at P = 1 and 3. Runs mpirun and the interpreter itself
// (label "mpi").
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include "cli_runner.hpp"
#include "mpi_launcher.hpp"
#include "oxide_sweep_case.hpp"
#include "same_outputs.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;

namespace {
const ScratchDir work_scratch("wearscale_mpi_python_run_");
const fs::path work = work_scratch.path();

// tests/mpi/run_sweep.py on `ranks` ranks (0: without mpirun), one thread a rank.
CliResult run(int ranks, const std::string& out) {
  write_oxide_sweep_case(work, "0, 1e-6, \"inf\"");
  const std::string launcher = mpi_launcher(ranks) + " ";
  const auto so = work / "py.stdout", se = work / "py.stderr";
  const std::string cmd = "cd '" + work.string() + "' && CI=true OMP_NUM_THREADS=1 PYTHONPATH='" WEARSCALE_PYTHONPATH
                          "' " + launcher + WEARSCALE_PYTHON " '" WEARSCALE_SOURCE_DIR "/tests/mpi/run_sweep.py' sweep.toml " +
                          out + " >'" + so.string() + "' 2>'" + se.string() + "'";
  const int raw = std::system(cmd.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(so), slurp(se)};
}
}  // namespace

TEST(MpiPythonRun, OneAndThreeRanksGiveTheSerialOutputs) {
  const auto serial = run(0, "serial");
  ASSERT_EQ(serial.status, 0) << serial.err;
  EXPECT_NE(serial.out.find("ranks 1:"), std::string::npos) << serial.out;
  ASSERT_TRUE(fs::exists(work / "serial/friction_vs_thickness.csv"));
  for (int ranks : {1, 3}) {
    const std::string dir = "np" + std::to_string(ranks);
    const auto r = run(ranks, dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("ranks " + std::to_string(ranks) + ":"), std::string::npos) << "said once, by rank 0:\n" << r.out;
    EXPECT_EQ(r.out.find("ranks", r.out.find("ranks") + 1), std::string::npos) << "said once, by rank 0:\n" << r.out;
    same_outputs::expect_same_outputs(work / "serial", work / dir, same_outputs::Timings::Ignored);
  }
}
