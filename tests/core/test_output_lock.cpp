// One writer per output folder: a second process is refused naming the
// holder's pid; a killed holder's lock is free at once; a folder the lock
// created and nothing was written into is removed again.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/output_lock.hpp"
#include "scratch_dir.hpp"

using namespace wearscale;
namespace fs = std::filesystem;

namespace {
fs::path scratch(const std::string& name) {
  static const ScratchDir scratch("wearscale_output_lock_");
  return scratch.path() / name;
}

// A child process holding the lock of `dir` until killed; returns its pid once it holds it.
pid_t holder_of(const fs::path& dir) {
  int ready[2];
  if (::pipe(ready) != 0) return -1;
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(ready[0]);
    try {
      const OutputLock lock = OutputLock::folder(dir, "wearscale run holder.toml");
      const char ok = 1;
      (void)!::write(ready[1], &ok, 1);
      for (;;) ::pause();
    } catch (...) {
      ::_exit(1);
    }
  }
  ::close(ready[1]);
  char ok = 0;
  (void)!::read(ready[0], &ok, 1);
  ::close(ready[0]);
  return ok == 1 ? child : -1;
}
}  // namespace

TEST(OutputLock, ASecondWriterIsRefusedNamingTheHoldersPid) {
  const auto dir = scratch("busy");
  const pid_t holder = holder_of(dir);
  ASSERT_GT(holder, 0);
  try {
    OutputLock::folder(dir, "wearscale run other.toml");
    ADD_FAILURE() << "the second lock was granted";
  } catch (const OutputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr(fmt::format("is being written by process {}", holder)));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("wearscale run holder.toml"));
  }
  ::kill(holder, SIGKILL);  // SIGKILL: no clean-up at all
  int status = 0;
  ::waitpid(holder, &status, 0);
  EXPECT_NO_THROW({ const OutputLock again = OutputLock::folder(dir, "wearscale run other.toml"); })
      << "the lock of a killed process is free";
  EXPECT_FALSE(fs::exists(dir / OutputLock::kFolderLockName)) << "released: the lock file is removed";
  fs::remove_all(dir.parent_path());
}

TEST(OutputLock, AFolderItCreatedStaysOnlyIfSomethingWasWrittenIntoIt) {
  const auto empty = scratch("a") / "b" / "c", used = scratch("used");
  { const OutputLock lock = OutputLock::folder(empty, "test"); EXPECT_TRUE(fs::is_directory(empty)); }
  EXPECT_FALSE(fs::exists(scratch("a"))) << "created and left empty: removed up to the first folder it created";
  {
    const OutputLock lock = OutputLock::folder(used, "test");
    std::ofstream(used / "result.csv") << "1\n";
  }
  EXPECT_TRUE(fs::exists(used / "result.csv"));
  fs::remove_all(used.parent_path());
}

TEST(OutputLock, OneOutputFileIsLockedBesideItAndFoldersThatCannotBeWrittenAreRefused) {
  const auto dir = scratch("files");
  fs::create_directories(dir);
  {
    const OutputLock a = OutputLock::file(dir / "a.h5", "one");
    const OutputLock b = OutputLock::file(dir / "b.h5", "two");  // another file of the same folder: fine
    EXPECT_TRUE(fs::exists(dir / ".a.h5.lock"));
  }
  EXPECT_TRUE(fs::is_empty(dir));
  EXPECT_THROW(OutputLock::folder("/proc/self", "test"), OutputError);
  std::ofstream(dir / "plain") << "x";
  EXPECT_THROW(OutputLock::folder(dir / "plain", "test"), OutputError);  // a file where the folder should be
  fs::remove_all(dir.parent_path());
}

// Shards of one ensemble (--task K/N) share a folder; another ensemble's
// shards and an exclusive writer are refused while any shard holds it, and a
// shard is refused while an exclusive writer holds it. (flock conflicts
// between open files, so one process can play several shards.)
TEST(OutputLock, ShardsOfOneEnsembleShareAFolderAndNobodyElse) {
  const auto dir = scratch("shards");
  {
    const OutputLock a = OutputLock::folder(dir, "wearscale run s.toml --task 1/2", OutputLock::Mode::Shared, "E1");
    const OutputLock b = OutputLock::folder(dir, "wearscale run s.toml --task 2/2", OutputLock::Mode::Shared, "E1");
    try {
      OutputLock::folder(dir, "wearscale run s.toml");
      ADD_FAILURE() << "an exclusive lock was granted beside shards";
    } catch (const OutputError& e) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr("is being written by process"));
      EXPECT_THAT(e.what(), ::testing::HasSubstr("--task 1/2"));  // the first shard's command
    }
    try {
      OutputLock::folder(dir, "wearscale run t.toml --task 1/3", OutputLock::Mode::Shared, "E2");
      ADD_FAILURE() << "a shard of another ensemble was admitted";
    } catch (const OutputError& e) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr("shards of another ensemble"));
    }
    {
      const OutputLock c = OutputLock::folder(dir, "wearscale run s.toml --task 1/5", OutputLock::Mode::Shared, "E1");
    }  // a shard that leaves while others hold the folder leaves the lock file to them
    EXPECT_TRUE(fs::exists(dir / OutputLock::kFolderLockName));
  }
  EXPECT_FALSE(fs::exists(dir / OutputLock::kFolderLockName));  // the last shard removed it
  {
    const OutputLock whole = OutputLock::folder(dir, "wearscale merge shards");
    try {
      OutputLock::folder(dir, "wearscale run s.toml --task 1/2", OutputLock::Mode::Shared, "E1");
      ADD_FAILURE() << "a shard was admitted beside an exclusive writer";
    } catch (const OutputError& e) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr("wearscale merge shards"));
    }
  }
  // A killed run's lock file (no holder) does not keep a shard out.
  std::ofstream(dir / OutputLock::kFolderLockName) << "pid: 1\nhost: gone\ncommand: wearscale run old.toml\n";
  const OutputLock again = OutputLock::folder(dir, "wearscale run s.toml --task 2/2", OutputLock::Mode::Shared, "E3");
}
