// Every command's --help ends in Examples that run as they are:
// one test per example, read from `wearscale --help-all` when the tests are
// listed, each run in its own scratch folder (cases/ linked beside it) after
// the examples before it in the same help (an example may read what an earlier
// one wrote), and every CSV table it writes checked against the table rules
// (tests/support/csv_table_check.hpp). The examples are small: the whole set
// costs seconds; those of `dem` and `strength-table` are the slow ones.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "csv_table_check.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;

namespace {
const ScratchDir work_scratch("wearscale_examples_");
const fs::path work = work_scratch.path();

struct Example {
  std::string command;                // "dem patch-test", "" for the program itself
  std::size_t index;                  // its place in the command's Examples
  std::vector<std::string> examples;  // all of the command's examples
};

// `wearscale --help-all`, written by the build (every test process lists the
// examples: reading a file is cheaper than starting the program each time).
std::string help_all() { return slurp(WEARSCALE_HELP_ALL); }

// The commands of --help-all (headings "wearscale <command>:") with their examples.
std::vector<std::pair<std::string, std::vector<std::string>>> commands_and_examples() {
  std::vector<std::pair<std::string, std::vector<std::string>>> out = {{"", {}}};
  std::istringstream in(help_all());
  std::string line;
  bool in_examples = false;
  while (std::getline(in, line)) {
    if (line.starts_with("wearscale ") && line.ends_with(":")) {
      out.push_back({line.substr(10, line.size() - 11), {}});
      in_examples = false;
    } else if (line == "Examples:") {
      in_examples = true;
    } else if (in_examples && line.starts_with("  ")) {
      out.back().second.push_back(line.substr(2));
    } else {
      in_examples = false;
    }
  }
  return out;
}

// The test's name in ctest: the command and the example's place.
void PrintTo(const Example& e, std::ostream* os) {
  *os << "wearscale" << (e.command.empty() ? "" : " ") << e.command << " #" << e.index;
}

std::vector<Example> all_examples() {
  std::vector<Example> out;
  for (const auto& [command, examples] : commands_and_examples())
    for (std::size_t k = 0; k < examples.size(); ++k) out.push_back({command, k, examples});
  return out;
}

std::string test_name(const ::testing::TestParamInfo<Example>& info) {
  std::string name = info.param.command.empty() ? "wearscale" : info.param.command;
  for (auto& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name + "_" + std::to_string(info.param.index);
}

std::string single_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// Runs one example line under bash with `wearscale` the program under test.
CliResult run_example(const std::string& line, const fs::path& dir) {
  const std::string script = "wearscale() { '" + std::string(WEARSCALE_CLI) + "' \"$@\"; }\n" + line + "\n";
  const auto out = dir / "example.stdout", err = dir / "example.stderr";
  const std::string cmd = "cd '" + dir.string() + "' && CI=true WEARSCALE_CACHE='" + (dir / "cache").string() +
                          "' bash -c " + single_quoted(script) + " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int raw = std::system(cmd.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
}

class HelpExample : public ::testing::TestWithParam<Example> {};
}  // namespace

TEST_P(HelpExample, RunsAndWritesCleanTables) {
  const Example& e = GetParam();
  const std::string& line = e.examples[e.index];
  if (line.find("strength-table") != std::string::npos && std::system("command -v lmp >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "LAMMPS (lmp) is not on PATH: the strength-table example is not run";
  const fs::path dir = work / test_name({e, 0});
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::create_directory_symlink(fs::path(WEARSCALE_SOURCE_DIR) / "cases", dir / "cases");
  for (std::size_t k = 0; k < e.index; ++k) {
    const auto before = run_example(e.examples[k], dir);
    ASSERT_EQ(before.status, 0) << "the example before it, " << e.examples[k] << "\n" << before.err;
  }
  const auto r = run_example(line, dir);
  ASSERT_EQ(r.status, 0) << line << "\n" << r.err;
  std::size_t tables = 0;
  for (const auto& problem : csv_check::problems_under(dir, tables)) ADD_FAILURE() << problem;
  RecordProperty("tables", static_cast<int>(tables));
}

INSTANTIATE_TEST_SUITE_P(Help, HelpExample, ::testing::ValuesIn(all_examples()), test_name);

TEST(HelpExamples, EveryCommandHasSome) {
  const auto commands = commands_and_examples();
  EXPECT_GT(commands.size(), 15u) << "the commands of --help-all were not found";
  for (const auto& [command, examples] : commands) {
    EXPECT_FALSE(examples.empty()) << "'wearscale " << command << " --help' has no Examples";
    bool runs_itself = command.empty();
    for (const auto& line : examples) runs_itself = runs_itself || line.find("wearscale " + command) != std::string::npos;
    EXPECT_TRUE(runs_itself) << "no example of 'wearscale " << command << "' runs it";
  }
}
