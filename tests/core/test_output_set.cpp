// The outputs of one run appear together: staged under temporary names until
// the set commits, the manifest (summary) removed first and written last, the
// previous run's other outputs removed; an uncommitted set leaves nothing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/output_set.hpp"
#include "wearscale/io/csv.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "scratch_dir.hpp"

using namespace wearscale;
namespace fs = std::filesystem;

namespace {
fs::path scratch(const std::string& name) {
  static const ScratchDir dir_scratch("wearscale_output_set_");
  const std::filesystem::path dir = dir_scratch.path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

std::string text_of(const fs::path& p) {
  std::stringstream ss;
  ss << std::ifstream(p).rdbuf();
  return ss.str();
}
}  // namespace

TEST(OutputSet, FilesStayUnderTemporaryNamesUntilTheSetCommits) {
  const auto dir = scratch("staged");
  {
    OutputSet set(dir, "summary.json");
    write_file_atomically(dir / "table.csv", "a,b\n1,2\n");
    H5Writer h5(dir / "run.h5");
    h5.write_series("/x", std::vector<double>{1.0});
    h5.commit();
    EXPECT_FALSE(fs::exists(dir / "table.csv"));
    EXPECT_FALSE(fs::exists(dir / "run.h5"));
    EXPECT_EQ(text_of(OutputSet::readable(dir / "table.csv")), "a,b\n1,2\n");  // the run can read its own outputs
    EXPECT_EQ(set.staged().size(), 2u);
    set.commit({{"results", {{"x", 1}}}});
  }
  EXPECT_EQ(names_in(dir), (std::vector<std::string>{"run.h5", "summary.json", "table.csv"}));
  const auto manifest = nlohmann::json::parse(text_of(dir / "summary.json"));
  EXPECT_EQ(manifest["outputs"]["table.csv"]["bytes"], 8);
  EXPECT_EQ(manifest["results"]["x"], 1);
  EXPECT_EQ(OutputSet::verify(dir, manifest), "");
  // A damaged output no longer matches its manifest.
  std::ofstream(dir / "table.csv", std::ios::trunc) << "a,b\n";
  EXPECT_THAT(OutputSet::verify(dir, manifest), ::testing::HasSubstr("table.csv: 4 bytes"));
  fs::remove_all(dir);
}

TEST(OutputSet, AnUncommittedSetLeavesThePreviousRunAsItWas) {
  const auto dir = scratch("failed");
  {
    OutputSet first(dir, "summary.json");
    write_file_atomically(dir / "table.csv", "first\n");
    first.commit({{"run", 1}});
  }
  try {
    OutputSet second(dir, "summary.json");
    write_file_atomically(dir / "table.csv", "second\n");
    write_file_atomically(dir / "friction.csv", "second\n");
    throw std::runtime_error("the solver failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(names_in(dir), (std::vector<std::string>{"summary.json", "table.csv"})) << "no temporary file left";
  EXPECT_EQ(text_of(dir / "table.csv"), "first\n");
  EXPECT_EQ(nlohmann::json::parse(text_of(dir / "summary.json"))["run"], 1);
  fs::remove_all(dir);
}

TEST(OutputSet, ANewSetReplacesThePreviousOneWhole) {
  const auto dir = scratch("replace");
  {
    OutputSet first(dir, "summary.json");
    write_file_atomically(dir / "a.csv", "1\n");
    write_file_atomically(dir / "old_only.png", "1\n");
    first.commit({{"run", 1}});
  }
  std::ofstream(dir / "notes.txt") << "the user's own file\n";
  {
    OutputSet second(dir, "summary.json");
    write_file_atomically(dir / "a.csv", "2\n");
    write_file_atomically(dir / "a.csv", "2, again\n");  // written twice: the last version counts
    second.commit({{"run", 2}});
  }
  EXPECT_EQ(names_in(dir), (std::vector<std::string>{"a.csv", "notes.txt", "summary.json"}))
      << "outputs of the previous run it did not write again are gone; files it never listed stay";
  EXPECT_EQ(text_of(dir / "a.csv"), "2, again\n");
  fs::remove_all(dir);
}

TEST(OutputSet, ImmediateCommitsAndOtherFoldersBypassTheSet) {
  const auto dir = scratch("bypass");
  fs::create_directories(dir / "sub");
  OutputSet set(dir, "summary.json");
  write_file_atomically(dir / "checkpoint.h5", "state\n", Commit::Now);
  write_file_atomically(dir / "sub" / "x.csv", "x\n");
  EXPECT_TRUE(fs::exists(dir / "checkpoint.h5"));
  EXPECT_TRUE(fs::exists(dir / "sub" / "x.csv"));
  EXPECT_TRUE(set.staged().empty());
  fs::remove_all(dir);
}

TEST(AtomicFile, AWriteThatFailsLeavesNoFileAndNamesThePath) {
  try {
    write_file_atomically("/proc/self/summary.json", "{}\n");
    FAIL() << "no OutputError";
  } catch (const OutputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("/proc/self/summary.json"));
  }
  EXPECT_THROW(write_csv("/proc/self/x.csv", {"a"}, {std::vector<double>{1.0}}, {"1"}), OutputError);
}

// A sweep's runs are its set too: the next run of the folder removes the run
// folders the previous summary listed and it does not own again (and the
// series folders they leave empty), and never a folder no summary listed.
TEST(OutputSet, TheRunFoldersAPreviousSetOwnedGoWhenTheNextDoesNotOwnThem) {
  const auto dir = scratch("folders");
  for (const char* run : {"v=1", "v=2", "s=a/v=1", "s=b/v=1", "mine"}) {
    fs::create_directories(dir / run);
    write_file_atomically(dir / run / "summary.json", "{}\n", Commit::Now);
  }
  {
    OutputSet set(dir, "summary.json");
    for (const char* run : {"v=1", "v=2", "s=a/v=1", "s=b/v=1"}) set.own_folder(run);
    set.commit(nlohmann::json::object());
  }
  const auto listed = nlohmann::json::parse(text_of(dir / "summary.json"))["folders"];
  EXPECT_EQ(listed.size(), 4u);
  {
    OutputSet set(dir, "summary.json");
    set.own_folder("v=2");
    set.own_folder("s=a/v=1");
    set.commit(nlohmann::json::object());
  }
  EXPECT_FALSE(fs::exists(dir / "v=1"));
  EXPECT_TRUE(fs::exists(dir / "v=2" / "summary.json"));
  EXPECT_TRUE(fs::exists(dir / "s=a" / "v=1" / "summary.json"));
  EXPECT_FALSE(fs::exists(dir / "s=b")) << "the series folder its only run left";
  EXPECT_TRUE(fs::exists(dir / "mine" / "summary.json")) << "no summary listed it: not the set's to remove";
  OutputSet set(dir, "summary.json");
  for (const char* bad : {"..", "../x", "/tmp", ".hidden", "a/b/c", ""})
    EXPECT_THROW(set.own_folder(bad), std::invalid_argument) << bad;
}
