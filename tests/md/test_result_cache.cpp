// The result cache: identical inputs do not call lmp again.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <thread>

#include "md_test_support.hpp"
#include "wearscale/materials/strength_table.hpp"
#include "wearscale/md/lammps_runner.hpp"
#include "wearscale/md/result_cache.hpp"
#include "wearscale/md/shear_study.hpp"

using namespace wearscale;
using namespace wearscale::md;

namespace {
long lines(const std::filesystem::path& p) {
  const std::string s = md_test::read(p);
  return std::count(s.begin(), s.end(), '\n');
}
}  // namespace

TEST(ResultCache, SecondIdenticalStudyDoesNotRunLmp) {
  const auto dir = md_test::temp_dir("cache-study");
  const auto counter = dir / "calls.txt";
  ShearTestSpec s = preset_spec("Si", "smoke");
  s.pressures = {0.0, 10e9};
  s.lmp = md_test::fake_lmp(dir, counter).string();
  s.ranks = 1;
  s.cache_dir = dir / "cache";
  md_test::write(dir / "Si.sw", md_test::si_sw);
  s.model.potential = dir / "Si.sw";

  const ShearStudy first = run_shear_study(s);
  EXPECT_EQ(lines(counter), 5) << "lmp -h once, the elastic constants of the ideal lattice and of the sample, then "
                                  "one run per pressure";
  ASSERT_EQ(first.points.size(), 2u);
  EXPECT_FALSE(first.points[0].run.cached);
  EXPECT_NEAR(first.points[1].strength.sigma_max, 12e9, 1e-3);
  EXPECT_NEAR(first.points[1].strength.sigma_dyn, 2e9, 1e-3);

  const ShearStudy second = run_shear_study(s);
  EXPECT_EQ(lines(counter), 5) << "nothing ran: versions and results came from the cache";
  EXPECT_TRUE(second.points[0].run.cached);
  EXPECT_TRUE(second.points[1].run.cached);
  EXPECT_EQ(second.points[1].run.folder, first.points[1].run.folder);
  EXPECT_DOUBLE_EQ(second.points[1].strength.sigma_dyn, first.points[1].strength.sigma_dyn);

  // A changed input (seed) is a new key: lmp runs again, once per pressure
  // (the 0 K elastic constants do not depend on the seed: cached).
  s.seed = 5;
  run_shear_study(s);
  EXPECT_EQ(lines(counter), 7);
  // A changed potential file is a new key for every run.
  md_test::write(dir / "Si.sw", std::string(md_test::si_sw) + "# edited\n");
  run_shear_study(s);
  EXPECT_EQ(lines(counter), 11);
  // Caching off: always runs.
  s.use_cache = false;
  run_shear_study(s);
  EXPECT_EQ(lines(counter), 15);
}

TEST(ResultCache, TableCarriesProvenance) {
  const auto dir = md_test::temp_dir("cache-table");
  ShearTestSpec s = preset_spec("Si", "smoke");
  s.pressures = {0.0, 5e9};
  s.lmp = md_test::fake_lmp(dir, dir / "calls.txt").string();
  s.cache_dir = dir / "cache";
  md_test::write(dir / "Si.sw", md_test::si_sw);
  s.model.potential = dir / "Si.sw";
  const materials::StrengthTable t = strength_table(run_shear_study(s));
  EXPECT_EQ(t.material, "Si");
  ASSERT_EQ(t.pressure.size(), 2u);
  EXPECT_DOUBLE_EQ(t.pressure[1], 5e9);
  for (const char* key : {"source", "material", "lammps_version", "lammps_command", "potential", "potential_sha256",
                          "system_size", "atoms", "elastic_check", "elastic_reference", "shear_modulus", "temperature",
                          "thermostat", "shear_velocity", "shear_rate", "strain_window", "seeds", "date",
                          "cost_per_point"})
    EXPECT_FALSE(t.info(key).empty()) << key;
  EXPECT_EQ(t.info("lammps_version"), "1 Jan 2000 - fake");
  EXPECT_EQ(t.info("atoms"), "544");
  EXPECT_EQ(t.info("potential_sha256").size(), 64u) << "the SHA-256 of the file the runs read, whole";
}

TEST(ResultCache, KeysAndEntries) {
  EXPECT_NE(cache_key({"ab", "c"}), cache_key({"a", "bc"}));
  EXPECT_EQ(cache_key({"x"}).size(), 64u);
  const auto dir = md_test::temp_dir("cache-entries");
  ResultCache c(dir);
  EXPECT_FALSE(c.find("k"));
  const auto work = c.begin("k");
  md_test::write(work / "out.txt", "1");
  EXPECT_FALSE(c.find("k")) << "a running (partial) entry is not found";
  const auto e = c.commit("k", work);
  ASSERT_TRUE(c.find("k"));
  EXPECT_EQ(md_test::read(e / "out.txt"), "1");
  EXPECT_FALSE(std::filesystem::exists(work));
}

// One writer per entry: processes (the ranks of an MPI job, a job array's
// tasks) and threads asking for the same runs at once run each once; the
// others wait for it and read its entry, and no partial folder is left.
TEST(ResultCache, ProcessesAndThreadsAskingTheSameRunRunItOnce) {
  const auto dir = md_test::temp_dir("cache-one-writer");
  const auto counter = dir / "calls.txt";
  const auto fake = md_test::fake_lmp(dir, counter);
  // Slow enough that every asker arrives while the first one runs.
  const auto slow = dir / "slow-lmp";
  md_test::write(slow, "#!/bin/sh\n[ \"$1\" = \"-h\" ] || sleep 1\nexec '" + fake.string() + "' \"$@\"\n");
  std::filesystem::permissions(slow, std::filesystem::perms::owner_all);
  ShearTestSpec s = preset_spec("Si", "smoke");
  s.pressures = {0.0, 10e9};
  s.lmp = slow.string();
  s.cache_dir = dir / "cache";
  md_test::write(dir / "Si.sw", md_test::si_sw);
  s.model.potential = dir / "Si.sw";
  (void)lammps_version(slow, s.cache_dir);  // `lmp -h` once, before the race

  std::vector<pid_t> children;
  for (int p = 0; p < 3; ++p) {
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      int status = 0;
      try {
        const ShearStudy st = run_shear_study(s);
        status = st.points.size() == 2 && st.points[1].strength.sigma_max > 11e9 ? 0 : 3;
      } catch (const std::exception&) {
        status = 4;
      }
      ::_exit(status);
    }
    children.push_back(pid);
  }
  std::vector<ShearStudy> in_threads(2);
  {
    std::vector<std::thread> threads;
    for (auto& st : in_threads) threads.emplace_back([&st, &s] { st = run_shear_study(s); });
    for (auto& t : threads) t.join();
  }
  for (const pid_t pid : children) {
    int status = -1;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "a process got no complete study";
  }
  const std::string calls = md_test::read(counter);
  EXPECT_EQ(std::count(calls.begin(), calls.end(), '\n'), 5)
      << "lmp -h once, the two elastic-constant runs once, then each pressure once:\n" << calls;
  for (const auto& st : in_threads) {
    ASSERT_EQ(st.points.size(), 2u);
    EXPECT_EQ(st.points[1].run.folder, in_threads[0].points[1].run.folder);
    EXPECT_EQ(st.points[1].strength.sigma_max, in_threads[0].points[1].strength.sigma_max);
  }
  for (const auto& e : std::filesystem::directory_iterator(s.cache_dir))
    EXPECT_EQ(e.path().filename().string().find(".partial-"), std::string::npos) << e.path();
}
