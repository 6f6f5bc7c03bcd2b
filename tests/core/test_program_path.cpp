// Where an external program is: the first executable regular file of that
// name in the directories of PATH, as a shell finds it, or nothing.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "scratch_dir.hpp"
#include "wearscale/core/program_path.hpp"

namespace fs = std::filesystem;
using wearscale::find_on_path;

namespace {
const ScratchDir scratch("wearscale_program_path_");

void make_file(const fs::path& p, fs::perms perms) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << "#!/bin/sh\n";
  fs::permissions(p, perms);
}

// PATH set for one test, restored after it.
class WithPath {
 public:
  explicit WithPath(const std::string& value) {
    if (const char* p = std::getenv("PATH")) saved_ = p;
    ::setenv("PATH", value.c_str(), 1);
  }
  ~WithPath() { ::setenv("PATH", saved_.c_str(), 1); }
  WithPath(const WithPath&) = delete;
  WithPath& operator=(const WithPath&) = delete;

 private:
  std::string saved_;
};
}  // namespace

TEST(ProgramPath, TheFirstExecutableOfThatNameOnPathIsFound) {
  const auto a = scratch.file("a"), b = scratch.file("b");
  make_file(a / "tool", fs::perms::owner_read | fs::perms::owner_write);  // not executable
  make_file(b / "tool", fs::perms::owner_all);
  fs::create_directories(scratch.file("c") / "tool");  // a directory of that name
  const WithPath path("::" + scratch.file("c").string() + ":" + a.string() + ":" + b.string());
  EXPECT_EQ(find_on_path("tool"), b / "tool");
}

TEST(ProgramPath, AProgramNotOnPathIsNotFound) {
  const WithPath path(scratch.file("a").string());
  EXPECT_TRUE(find_on_path("no-such-program-wearscale").empty());
  EXPECT_TRUE(find_on_path("").empty());
}
