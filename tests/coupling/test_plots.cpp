// Legends and titles of the sweep figures: a run folder's name as a reader
// would write it; a signal while gnuplot draws stops the run.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "scratch_dir.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/coupling/plots.hpp"

using wearscale::coupling::legend_label;

TEST(Plots, LegendsNameTheOxideThicknessInMicrometres) {
  EXPECT_EQ(legend_label("thickness=5e-07"), "h = 0.5 µm");
  EXPECT_EQ(legend_label("thickness=3e-06"), "h = 3 µm");
  EXPECT_EQ(legend_label("thickness=0"), "h = 0 (no oxide)");
  EXPECT_EQ(legend_label("thickness=inf"), "h = ∞ (bulk oxide)");
}

TEST(Plots, OtherLegendsKeepTheirKeyAndValue) {
  EXPECT_EQ(legend_label("slope=0.02 layer_test=disc"), "slope = 0.02, layer_test = disc");
  EXPECT_EQ(legend_label("pin-on-disc-si-oxide"), "pin-on-disc-si-oxide");
  EXPECT_EQ(legend_label("thickness=thick"), "thickness = thick") << "not a number: as it is";
}

// The sweep figures' titles state the parameters the case sets, in the units a
// reader would write, and leave a swept key to the legends.
TEST(Plots, SweepTitlesStateTheLoadTheVelocityThePinAndTheSweptKey) {
  const auto c = wearscale::Config::from_string(
      "[materials]\npin = \"SiO2\"\ndisc = \"Si\"\n"
      "[scale.macro]\npin_radius = \"3 mm\"\nnormal_load = \"1 N\"\nvelocity = \"8 mm/s\"\n");
  EXPECT_EQ(wearscale::coupling::sweep_title(c, "oxide-thickness-sweep", "materials.layer.thickness"),
            "oxide-thickness-sweep\nSiO2 pin on Si disc, R = 3 mm, F_N = 1 N, v = 8 mm/s; "
            "swept: materials.layer.thickness");
  EXPECT_EQ(wearscale::coupling::sweep_title(c, "loads", "scale.macro.normal_load", "scale.macro.velocity"),
            "loads\nSiO2 pin on Si disc, R = 3 mm; swept: scale.macro.normal_load, series: scale.macro.velocity");
  EXPECT_EQ(wearscale::coupling::sweep_title(wearscale::Config::from_string(""), "bare", "k"), "bare\nswept: k")
      << "nothing set, nothing stated";
}

// Ctrl-C reaches the whole foreground process group: gnuplot, which answers
// SIGINT by exiting with status 1, and the run, which must stop rather than
// go on without the plot (and be taken as complete by a resume). SIGTERM to
// the group (a scheduler, mpirun) likewise. The drawing process is a child in
// a process group of its own; it says by its exit status what render_plot did.
TEST(Plots, ASignalToTheProcessGroupWhileGnuplotDrawsStopsTheRunWithoutThePlot) {
  if (!wearscale::coupling::plotting_available()) GTEST_SKIP() << "gnuplot is not installed";
  const ScratchDir scratch("wearscale_plot_signal_");
  for (const int signal : {SIGINT, SIGTERM}) {
    const auto dir = scratch.file(signal == SIGINT ? "int" : "term");
    std::filesystem::create_directories(dir);
    const auto ready = dir / "drawing", png = dir / "slow.png";
    // About 9 s of drawing on a 2-vCPU host; the signal comes as it begins.
    // gnuplot says it has started by a file of its own (`set print`, no shell:
    // a shell it waited for would keep SIGINT from it), then draws.
    const std::string script = "set print '" + ready.string() + "'\nprint 'drawing'\nset print\nset samples 1000\n"
                               "plot for [i=1:300] sin(x*i) notitle\n";
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      ::setpgid(0, 0);
      wearscale::install_interrupt_handlers();
      int outcome = 3;
      try {
        outcome = wearscale::coupling::render_plot(script, png) ? 0 : 1;
      } catch (const wearscale::Interrupted&) {
        outcome = 2;
      } catch (...) {
      }
      ::_exit(outcome);
    }
    for (int wait = 0; wait < 600 && !std::filesystem::exists(ready); ++wait)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    ASSERT_TRUE(std::filesystem::exists(ready)) << "gnuplot did not start";
    ASSERT_EQ(::kill(-child, signal), 0);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status)) << "signal " << signal << ": the drawing process itself was killed";
    EXPECT_EQ(WEXITSTATUS(status), 2) << "signal " << signal << ": 0 drawn, 1 left out as if gnuplot had failed, 3 another error";
    EXPECT_FALSE(std::filesystem::exists(png)) << "signal " << signal;
  }
}
