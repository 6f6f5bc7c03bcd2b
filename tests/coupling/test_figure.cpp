// How a figure reaches gnuplot: its texts as hexadecimal UTF-8 in a file of
// their own, decoded by gnuplot into strings byte for byte, never parsed; the
// figure drawn as a PNG and a PDF with its script kept beside them; a signal
// while gnuplot draws stops the run.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "scratch_dir.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/coupling/figure.hpp"

namespace fs = std::filesystem;
using wearscale::coupling::draw_figures;
using wearscale::coupling::Figure;
using wearscale::coupling::figure_text;

namespace {
std::string slurp_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Texts a user may give (case names, folders, values) that mean something to
// gnuplot, a shell or gnuplot's enhanced text.
const std::vector<std::string> kHostile = {
    "x'; system('touch PWNED'); print('",
    "\"; system(\"touch PWNED\"); print(\"",
    "back\\slash \\n \\\\",
    "$(touch PWNED) `touch PWNED`",
    "@ARG0 @name eval",
    "µm³ ∞ 日本 Ω",
    "  leading and trailing spaces  ",
    "#hash _sub^sup {brace} &amp ~tilde",
    "",
    "two\nlines"};

// A kind that prints its texts back (gnuplot's `set print` to a file of its
// folder), then draws a line titled by each (|TEXT|: how many there are).
const std::string kEcho = R"gp(n = |TEXT|
set print "echo.txt"
do for [k=1:n] { print "[".given_text(k)."]" }
set print
do for [FORMAT in "png pdf"] {
if (FORMAT eq "png") { set terminal pngcairo size 400,300 } else { set terminal pdfcairo size 4in,3in }
set output name.".".FORMAT
set title given_text(1) noenhanced
plot for [k=1:n] x*k title given_text(k) noenhanced
unset output
}
)gp";
}  // namespace

TEST(Figure, TextsAreWrittenAsHexadecimalUtf8AfterAnX) {
  Figure f{"f", "", {}, {}};
  f.add("title", "a'\n");
  f.add("empty", "");
  f.add("a\tnumber", 1e9);
  EXPECT_EQ(wearscale::coupling::figure_texts_file(f),
            "title\tx61270a\nempty\tx\na number\tx312e30303030303030303030303030303030652b3039\n")
      << "1e9 as 1.0000000000000000e+09: gnuplot's real() refuses \"1e9\"";
}

TEST(Figure, FigureTextsKeepPrintableUnicodeAndLoseControlCharacters) {
  EXPECT_EQ(figure_text("µm³ ∞\tx\r\n"), "µm³ ∞ x  ");
  EXPECT_EQ(figure_text("a\nb", 120, true), "a\nb");
  EXPECT_EQ(figure_text("a\xff" "b"), "a\uFFFD" "b") << "a byte that is not UTF-8";
  EXPECT_EQ(figure_text("µµµµ", 2), "µµ…");
  EXPECT_EQ(figure_text(std::string(200, 'x')).size(), 120u + std::string("…").size());
}

// The texts reach gnuplot as the very strings given, byte for byte, however
// hostile: none is read as a command (no file PWNED anywhere in the folder),
// and the figure is drawn with them.
TEST(Figure, GnuplotReadsEveryTextBackByteForByteAndRunsNone) {
  if (!wearscale::coupling::plotting_available()) GTEST_SKIP() << "gnuplot is not installed";
  const ScratchDir scratch("wearscale_figure_texts_");
  const fs::path folder = scratch.file("out 'x'; system('touch PWNED') $(id)");
  fs::create_directories(folder);
  Figure f{"echo", kEcho, {}, {}};
  for (const auto& t : kHostile) f.add("text", t);
  const auto files = draw_figures(folder, {f});
  ASSERT_EQ(files.size(), 4u) << "script, texts, PNG, PDF";
  for (const char* ext : {".png", ".pdf", ".gp"}) EXPECT_TRUE(fs::exists(folder / ("echo" + std::string(ext)))) << ext;
  EXPECT_TRUE(fs::exists(folder / "echo_labels.tsv"));
  std::error_code ec;
  for (const auto& e : fs::recursive_directory_iterator(scratch.path(), ec))
    EXPECT_NE(e.path().filename(), "PWNED") << e.path();
  EXPECT_FALSE(fs::exists("PWNED"));
  // The drawing's scratch folder (its echo.txt) is gone: the kept script again, in the folder, as a user runs it.
  const pid_t child = ::fork();
  if (child == 0) {
    if (::chdir(folder.c_str()) != 0) ::_exit(2);
    ::execlp("gnuplot", "gnuplot", "echo.gp", static_cast<char*>(nullptr));
    ::_exit(3);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "gnuplot echo.gp in the folder, as a user runs it";
  std::string expected;
  for (const auto& t : kHostile) expected += "[" + t + "]\n";
  EXPECT_EQ(slurp_file(folder / "echo.txt"), expected);
}

// gnuplot reads at most 1023 characters of a data field: a text of 70 000
// characters (a case's name) reaches it cut to 500 bytes, before a character,
// ending with an ellipsis, and the figure is drawn with it.
TEST(Figure, ATextLongerThanGnuplotReadsIsCutBeforeACharacterAndDrawn) {
  Figure f{"echo", kEcho, {}, {}};
  f.add("long", std::string(70000, 'x'));
  std::string micro;
  for (int k = 0; k < 400; ++k) micro += "µ";  // 2 bytes each: 800 bytes
  f.add("two-byte characters", "a" + micro);
  const std::string file = wearscale::coupling::figure_texts_file(f);
  std::istringstream lines(file);
  const std::string ellipsis_hex = "e280a6";  // "…"
  for (std::string line; std::getline(lines, line);) {
    const std::string hex = line.substr(line.find("\tx") + 2);
    EXPECT_EQ(hex.size() % 2, 0u);
    EXPECT_LE(hex.size() / 2, wearscale::coupling::kMaxTextBytes) << line.substr(0, 20);
    EXPECT_EQ(hex.substr(hex.size() - ellipsis_hex.size()), ellipsis_hex) << line.substr(0, 20);
  }
  // "a" then 248 whole µ (c2b5) fit in 500 - 3 bytes: the cut falls before a character.
  std::string cut_micro = "\tx61";
  for (int k = 0; k < 248; ++k) cut_micro += "c2b5";
  EXPECT_NE(file.find(cut_micro + ellipsis_hex + "\n"), std::string::npos);
  if (!wearscale::coupling::plotting_available()) GTEST_SKIP() << "gnuplot is not installed";
  const ScratchDir scratch("wearscale_figure_long_");
  const auto files = draw_figures(scratch.path(), {f});
  EXPECT_EQ(files.size(), 4u) << "script, texts, PNG, PDF";
  EXPECT_TRUE(fs::exists(scratch.file("echo.png")));
  EXPECT_TRUE(fs::exists(scratch.file("echo.pdf")));
}

// The same figure drawn twice is the same PNG and the same PDF, byte for
// byte (cairo's time stamp in the PDF is set to 1970-01-01): a resumed or
// repeated run rewrites its figures identically.
TEST(Figure, TheSameFigureDrawnTwiceIsTheSameBytes) {
  if (!wearscale::coupling::plotting_available()) GTEST_SKIP() << "gnuplot is not installed";
  const ScratchDir first("wearscale_figure_first_"), second("wearscale_figure_second_");
  Figure f{"echo", kEcho, {}, {}};
  f.add("title", "µm³ title");
  draw_figures(first.path(), {f});
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));  // another second on the clock
  draw_figures(second.path(), {f});
  for (const char* file : {"echo.png", "echo.pdf"}) {
    ASSERT_TRUE(fs::exists(first.file(file))) << file;
    EXPECT_TRUE(slurp_file(first.file(file)) == slurp_file(second.file(file))) << file;
  }
  EXPECT_NE(slurp_file(first.file("echo.pdf")).find("/CreationDate (D:19700101000000Z)"), std::string::npos);
}

// A gnuplot draws several of a folder's figures, their scripts one after the
// other: each script reads its own texts, whatever the script before it set
// (every one sets `columnheaders` for wearscale's tables, which `reset
// session` keeps). The kept scripts run together, as draw_figures runs them,
// exit 0 and print each its own texts (before, the second read its texts one
// line off, failed, and was drawn again on its own by another gnuplot).
TEST(Figure, FiguresDrawnByOneGnuplotEachReadTheirOwnTexts) {
  if (!wearscale::coupling::plotting_available()) GTEST_SKIP() << "gnuplot is not installed";
  const ScratchDir scratch("wearscale_figure_together_");
  const std::string echo = R"gp(set print name.".txt"
do for [k=1:|TEXT|] { print given_text(k) }
set print
slope = given_number(2)
do for [FORMAT in "png pdf"] {
if (FORMAT eq "png") { set terminal pngcairo size 400,300 } else { set terminal pdfcairo size 4in,3in }
set output name.".".FORMAT
plot slope*x title given_text(1) noenhanced
unset output
}
)gp";
  Figure first{"first", echo, {}, {}}, second{"second", echo, {}, {}};
  first.add("title", "first figure");
  first.add("slope", 1.0);
  second.add("title", "second figure");
  second.add("slope", 2.0);
  const auto files = draw_figures(scratch.path(), {first, second});
  EXPECT_EQ(files.size(), 8u) << "both scripts, texts, PNGs and PDFs";
  const pid_t child = ::fork();
  if (child == 0) {
    if (::chdir(scratch.path().c_str()) != 0) ::_exit(2);
    ::execlp("gnuplot", "gnuplot", "first.gp", "second.gp", static_cast<char*>(nullptr));
    ::_exit(3);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "gnuplot first.gp second.gp in the folder";
  EXPECT_EQ(slurp_file(scratch.file("first.txt")), "first figure\n1.0000000000000000e+00\n");
  EXPECT_EQ(slurp_file(scratch.file("second.txt")), "second figure\n2.0000000000000000e+00\n");
}

// One figure gnuplot cannot draw (its data missing) costs that figure only,
// with a warning: the others of the folder are drawn, and its script kept.
TEST(Figure, AFigureThatFailsLeavesTheOthersDrawn) {
  if (!wearscale::coupling::plotting_available()) GTEST_SKIP() << "gnuplot is not installed";
  const ScratchDir scratch("wearscale_figure_fail_");
  const std::string draw = "do for [FORMAT in \"png pdf\"] {\nif (FORMAT eq \"png\") { set terminal pngcairo } "
                           "else { set terminal pdfcairo }\nset output name.\".\".FORMAT\n"
                           "plot given_text(1) using 1:2 with lines\nunset output\n}\n";
  std::ofstream(scratch.file("good.csv")) << "a,b\n0.0,1.0\n1.0,2.0\n";
  Figure bad{"bad", draw, {}, {"missing.csv"}}, good{"good", draw, {}, {"good.csv"}};
  bad.add("table", "missing.csv");
  good.add("table", "good.csv");
  const auto files = draw_figures(scratch.path(), {bad, good});
  EXPECT_EQ(files.size(), 6u) << "both scripts and texts, the good figure's PNG and PDF";
  EXPECT_TRUE(fs::exists(scratch.file("good.png")));
  EXPECT_TRUE(fs::exists(scratch.file("good.pdf")));
  EXPECT_FALSE(fs::exists(scratch.file("bad.png")));
  EXPECT_TRUE(fs::exists(scratch.file("bad.gp")));
}

// Ctrl-C reaches the whole foreground process group: gnuplot, which answers
// SIGINT by exiting with status 1, and the run, which must stop rather than
// go on without the figure (and be taken as complete by a resume). SIGTERM to
// the group (a scheduler, mpirun) likewise. The drawing process is a child in
// a process group of its own; it says by its exit status what draw_figures did.
TEST(Plots, ASignalToTheProcessGroupWhileGnuplotDrawsStopsTheRunWithoutThePlot) {
  if (!wearscale::coupling::plotting_available()) GTEST_SKIP() << "gnuplot is not installed";
  const ScratchDir scratch("wearscale_plot_signal_");
  for (const int signal : {SIGINT, SIGTERM}) {
    const auto dir = scratch.file(signal == SIGINT ? "int" : "term");
    fs::create_directories(dir);
    // About 9 s of drawing on a 2-vCPU host; the signal comes as it begins.
    // gnuplot says it has started by a file of its own in its scratch folder
    // (`set print`, no shell: a shell it waited for would keep SIGINT from it).
    const Figure slow{"slow",
                      "set print \"drawing\"\nprint \"drawing\"\nset print\nset terminal pngcairo\n"
                      "set output name.\".png\"\nset samples 1000\nplot for [i=1:300] sin(x*i) notitle\n",
                      {{"title", "slow"}},
                      {}};
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      ::setpgid(0, 0);
      wearscale::install_interrupt_handlers();
      int outcome = 3;
      try {
        outcome = draw_figures(dir, {slow}).size() == 4 ? 0 : 1;
      } catch (const wearscale::Interrupted&) {
        outcome = 2;
      } catch (...) {
      }
      ::_exit(outcome);
    }
    auto started = [&] {
      std::error_code ec;
      for (const auto& e : fs::recursive_directory_iterator(dir, ec))
        if (e.path().filename() == "drawing") return true;
      return false;
    };
    for (int wait = 0; wait < 600 && !started(); ++wait) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    ASSERT_TRUE(started()) << "gnuplot did not start";
    ASSERT_EQ(::kill(-child, signal), 0);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status)) << "signal " << signal << ": the drawing process itself was killed";
    EXPECT_EQ(WEXITSTATUS(status), 2) << "signal " << signal
                                      << ": 0 drawn, 1 left out as if gnuplot had failed, 3 another error";
    EXPECT_FALSE(fs::exists(dir / "slow.png")) << "signal " << signal;
  }
}
