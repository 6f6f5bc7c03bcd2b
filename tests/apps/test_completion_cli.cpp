// `wearscale completion bash|zsh` and `--help-all`: scripts made from the
// parser that the shells accept and that complete commands, flags and the
// choices of a choice key; the help of every command at once (the man page).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>

#include "cli_runner.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_completion_");
const fs::path work = work_scratch.path();

fs::path script(const std::string& shell) {
  const auto r = run_cli("completion " + shell, work);
  EXPECT_EQ(r.status, 0) << r.err;
  const auto path = work / ("wearscale." + shell);
  std::ofstream(path) << r.out;
  return path;
}

bool on_path(const std::string& program) {
  return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

// What bash's completion offers for the words typed so far (the last one being completed).
std::string bash_offers(const fs::path& file, const std::string& words) {
  const auto out = work / "offers.txt";
  const std::string body = "source '" + file.string() + "'; COMP_WORDS=(wearscale " + words +
                           "); COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); _wearscale; echo \"${COMPREPLY[*]}\"";
  const std::string cmd = "bash -c '" + [&] {
    std::string q;
    for (char c : body) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q;
  }() + "' >'" + out.string() + "' 2>/dev/null";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  auto text = slurp(out);
  if (!text.empty() && text.back() == '\n') text.pop_back();
  return text;
}
}  // namespace

TEST(Completion, BashScriptParses) {
  const auto file = script("bash");
  EXPECT_EQ(std::system(("bash -n '" + file.string() + "'").c_str()), 0);
}

TEST(Completion, BashCompletesCommandsFlagsAndChoices) {
  const auto file = script("bash");
  EXPECT_EQ(bash_offers(file, "d"), "dem");
  EXPECT_EQ(bash_offers(file, "dem \"\""), "patch-test junction rough-shear trapped-particles oxide-asperity") << "subcommands";
  EXPECT_EQ(bash_offers(file, "dem patch-test --la"), "--lattice") << "a schema key's flag";
  EXPECT_EQ(bash_offers(file, "dem patch-test --lattice \"\""), "hcp amorphous") << "a choice key's values";
  EXPECT_EQ(bash_offers(file, "contact --friction t"), "tresca");
  EXPECT_EQ(bash_offers(file, "strength-table --preset t"), "thesis") << "a CLI::IsMember option";
  EXPECT_EQ(bash_offers(file, "completion z"), "zsh");
  EXPECT_EQ(bash_offers(file, "-q surface generate --hu"), "--hurst") << "past a global flag";
}

TEST(Completion, ZshScriptParses) {
  if (!on_path("zsh")) GTEST_SKIP() << "zsh is not installed: the zsh script is not checked";
  const auto file = script("zsh");
  EXPECT_THAT(slurp(file), HasSubstr("#compdef wearscale"));
  EXPECT_THAT(slurp(file), HasSubstr("compadd -- hcp amorphous"));
  EXPECT_EQ(std::system(("zsh -n '" + file.string() + "'").c_str()), 0);
}

TEST(Completion, AnUnknownShellIsRefused) {
  const auto r = run_cli("completion fish", work);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("fish"));
}

TEST(Completion, HelpAllPrintsEveryCommand) {
  const auto r = run_cli("--help-all", work);
  EXPECT_EQ(r.status, 0) << r.err;
  for (const char* usage : {"Usage: wearscale run ", "Usage: wearscale surface generate ",
                            "Usage: wearscale dem trapped-particles ", "Usage: wearscale wearmap rough ",
                            "Usage: wearscale completion "})
    EXPECT_THAT(r.out, HasSubstr(usage));
  EXPECT_THAT(r.out, HasSubstr("--lattice TEXT:{hcp,amorphous}")) << "choices in the help";
}
