// Finding and running lmp, without LAMMPS: a missing executable, a failing one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "md_test_support.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/program_path.hpp"
#include "wearscale/md/lammps_runner.hpp"

using namespace wearscale;
using namespace wearscale::md;

TEST(LammpsRunner, MissingLmpSaysHowToInstall) {
  try {
    find_lmp("/nonexistent/wearscale/lmp");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("apt-get install lammps"), std::string::npos) << e.what();
  }
  const char* old = std::getenv("PATH");
  const std::string saved = old != nullptr ? old : "";
  const auto empty = md_test::temp_dir("empty-path");
  ::setenv("PATH", empty.c_str(), 1);
  bool threw = false;
  try {
    find_lmp();
  } catch (const InputError& e) {
    threw = true;
    EXPECT_NE(std::string(e.what()).find("apt-get install lammps"), std::string::npos) << e.what();
  }
  ::setenv("PATH", saved.c_str(), 1);
  EXPECT_TRUE(threw);
}

TEST(LammpsRunner, FailureNamesRunFolderAndErrorLine) {
  const auto dir = md_test::temp_dir("failing");
  const auto lmp = dir / "lmp";
  md_test::write(lmp,
                 "#!/bin/sh\necho 'LAMMPS (fake)'\necho 'ERROR: Lost atoms: original 544 current 543 "
                 "(src/thermo.cpp:481)'\nexit 1\n");
  std::filesystem::permissions(lmp, std::filesystem::perms::owner_all);
  const auto run = dir / "run";
  std::filesystem::create_directories(run);
  md_test::write(run / "in.lammps", "run 10\n");
  try {
    run_lammps({lmp, 1, run, "in.lammps", "Si shear test at 0 GPa"});
    FAIL() << "expected NumericalError";
  } catch (const NumericalError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(run.string()), std::string::npos) << m;
    EXPECT_NE(m.find("ERROR: Lost atoms"), std::string::npos) << m;
    EXPECT_NE(m.find("Si shear test at 0 GPa"), std::string::npos) << m;
  }
}

TEST(LammpsRunner, ErrorLineWithZeroExitStillFails) {
  const auto dir = md_test::temp_dir("error-exit0");
  const auto lmp = dir / "lmp";
  md_test::write(lmp, "#!/bin/sh\necho 'ERROR on proc 0: Bond atoms missing'\nexit 0\n");
  std::filesystem::permissions(lmp, std::filesystem::perms::owner_all);
  EXPECT_THROW(run_lammps({lmp, 1, dir, "in.lammps", "x"}), NumericalError);
}

TEST(LammpsRunner, ARunFolderRelativeToTheWorkingDirectoryRuns) {
  // A relative cache folder (md.cache_dir = "cache") gives relative run folders: lmp still runs there.
  const auto dir = md_test::temp_dir("relative");
  const auto lmp = dir / "lmp";
  md_test::write(lmp, "#!/bin/sh\necho 'LAMMPS (fake)'\npwd > where.txt\n");
  std::filesystem::permissions(lmp, std::filesystem::perms::owner_all);
  std::filesystem::create_directories(dir / "cache" / "run");
  md_test::write(dir / "cache" / "run" / "in.lammps", "run 10\n");
  const auto previous = std::filesystem::current_path();
  std::filesystem::current_path(dir);
  EXPECT_NO_THROW(run_lammps({lmp, 1, "cache/run", "in.lammps", "relative run folder"}));
  std::filesystem::current_path(previous);
  EXPECT_TRUE(std::filesystem::exists(dir / "cache" / "run" / "where.txt"));
}

TEST(LammpsRunner, CommandUsesMpirunOnlyForSeveralRanks) {
  int used = 0;
  const auto one = lammps_command({"/usr/bin/lmp", 1, "/tmp", "in.lammps", ""}, used);
  EXPECT_EQ(used, 1);
  EXPECT_EQ(one.front(), "/usr/bin/lmp");
  const auto two = lammps_command({"/usr/bin/lmp", 2, "/tmp", "in.lammps", ""}, used);
  if (!find_on_path("mpirun").empty()) {
    EXPECT_EQ(used, 2);
    EXPECT_EQ(two[1], "--allow-run-as-root");
    EXPECT_EQ(two[3], "2");
  } else {
    EXPECT_EQ(used, 1);
  }
}

// From a rank of an MPI job lmp and its mpirun start a job of their own: the
// launcher's variables are dropped from their environment (Open MPI refuses a
// nested mpirun otherwise, "mpirun does not support recursive calls"), and
// that mpirun neither binds nor spins; outside a job the environment passes whole.
TEST(LammpsRunner, FromAnMpiRankTheChildGetsNoLauncherVariables) {
  auto has = [](const std::vector<std::string>& env, const std::string& prefix) {
    for (const auto& e : env)
      if (e.rfind(prefix, 0) == 0) return true;
    return false;
  };
  const char* launched[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK"};
  for (const char* v : launched) ::unsetenv(v);
  ::setenv("OMPI_MCA_btl", "self,vader", 1);
  ::setenv("SLURM_JOB_ID", "42", 1);
  ::setenv("WEARSCALE_TEST_KEEP", "1", 1);
  EXPECT_FALSE(is_mpi_rank());
  EXPECT_TRUE(has(child_environment(), "OMPI_MCA_btl=")) << "not a rank: the user's settings pass";
  int used = 0;
  const auto alone = lammps_command({"/usr/bin/lmp", 2, "/tmp", "in.lammps", ""}, used);
  EXPECT_EQ(std::count(alone.begin(), alone.end(), "--oversubscribe"), 0);

  ::setenv("OMPI_COMM_WORLD_SIZE", "3", 1);
  ::setenv("PMIX_RANK", "1", 1);
  EXPECT_TRUE(is_mpi_rank());
  const auto env = child_environment();
  for (const char* prefix : {"OMPI_", "PMIX_", "SLURM_"}) EXPECT_FALSE(has(env, prefix)) << prefix;
  EXPECT_TRUE(has(env, "WEARSCALE_TEST_KEEP=1"));
  EXPECT_TRUE(has(env, "PATH="));
  const auto nested = lammps_command({"/usr/bin/lmp", 2, "/tmp", "in.lammps", ""}, used);
  if (!find_on_path("mpirun").empty()) {
    EXPECT_EQ(std::count(nested.begin(), nested.end(), "--oversubscribe"), 1);
    EXPECT_EQ(std::count(nested.begin(), nested.end(), "mpi_yield_when_idle"), 1);
  }
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "OMPI_MCA_btl", "SLURM_JOB_ID", "WEARSCALE_TEST_KEEP"})
    ::unsetenv(v);
}

TEST(LammpsRunner, VersionFromHelpIsRemembered) {
  const auto dir = md_test::temp_dir("version");
  const auto counter = dir / "calls.txt";
  const auto lmp = md_test::fake_lmp(dir, counter);
  EXPECT_EQ(lammps_version(lmp, dir / "cache"), "1 Jan 2000 - fake");
  EXPECT_EQ(lammps_version(lmp, dir / "cache"), "1 Jan 2000 - fake");
  EXPECT_EQ(md_test::read(counter), "-h\n") << "the second call reads the remembered version";
}
