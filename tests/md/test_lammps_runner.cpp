// Finding and running lmp, without LAMMPS: a missing executable, a failing one.
#include <gtest/gtest.h>

#include <cstdlib>

#include "md_test_support.hpp"
#include "wearscale/core/errors.hpp"
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

TEST(LammpsRunner, VersionFromHelpIsRemembered) {
  const auto dir = md_test::temp_dir("version");
  const auto counter = dir / "calls.txt";
  const auto lmp = md_test::fake_lmp(dir, counter);
  EXPECT_EQ(lammps_version(lmp, dir / "cache"), "1 Jan 2000 - fake");
  EXPECT_EQ(lammps_version(lmp, dir / "cache"), "1 Jan 2000 - fake");
  EXPECT_EQ(md_test::read(counter), "-h\n") << "the second call reads the remembered version";
}
