// wearscale: friction and adhesive wear across scales.
//
// Exit status (docs/reliability.md): 0 success, 2 bad input (message names
// file, key, value and the allowed range) or an output that cannot be written
// (read-only, full, in use by another run: the path and the cause), 1
// numerical failure (message names solver, step, quantity), 130 stopped by
// SIGINT/SIGTERM (checkpoints saved, unfinished files removed), 3 internal
// error (a bug). Under mpirun/srun a rank that fails ends the whole job with
// its status (MPI_Abort), so that no rank waits for it.
#include <omp.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <map>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include <fmt/ranges.h>

#include "commands.hpp"
#include "completion.hpp"
#include "examples.hpp"
#include "parse_error.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/fft.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/core/task_farm.hpp"
#include "wearscale/core/version.hpp"

namespace {
bool every_rank_refused = false;  // a refusal (or failure) all ranks reach alike needs no abort
int run(int argc, char** argv);
}  // namespace

int main(int argc, char** argv) {
  wearscale::mpi::Session mpi_session(argc, argv);
  std::set_terminate([] { wearscale::mpi::abort(3); });
  const int status = run(argc, argv);
  if (status != 0 && wearscale::mpi::size() > 1 && !every_rank_refused) wearscale::mpi::abort(status);
  return status;
}

namespace {
// The first word that is neither an option nor an option's value, when it
// names no command (CLI11 would only say that a command is required).
std::optional<std::string> unknown_command(const CLI::App& app, int argc, char** argv) {
  for (int k = 1; k < argc; ++k) {
    const std::string word = argv[k];
    if (word == "-j" || word == "--threads") {
      ++k;  // its value
      continue;
    }
    if (word.starts_with("-")) continue;
    for (const auto* sub : app.get_subcommands({}))
      if (sub->check_name(word)) return std::nullopt;
    return word;
  }
  return std::nullopt;
}

int run(int argc, char** argv) {
  using namespace wearscale;
  CLI::App app{"wearscale: friction and adhesive wear across scales (MD → DEM/junctions → BEM pin-on-disc)",
               "wearscale"};
  app.require_subcommand(1);
  app.fallthrough();  // -q, -v, -j are accepted after the subcommand too
  bool quiet = false, verbose = false;
  int threads = 0;
  app.add_flag("-q,--quiet", quiet, "Only warnings and errors on stderr; no progress bar");
  app.add_flag("-v,--verbose", verbose, "Debug messages on stderr");
  app.add_option("-j,--threads", threads, "OpenMP and FFTW threads (default: all cores; under mpirun, the cores shared among the ranks of a node)")->check(CLI::Range(1, 1024));
  app.set_version_flag("--version", "wearscale " + version(), "Print the version of wearscale and exit");
  // Before the subcommands, which inherit it: every command's help at once (for help2man, the man page).
  app.set_help_all_flag("--help-all", "Print the help of every command and exit");

  std::map<CLI::App*, app::Command> commands;
  auto add = [&](app::Command (*adder)(CLI::App&)) {
    auto command = adder(app);
    commands[app.get_subcommands({}).back()] = std::move(command);  // the subcommand just added
  };
  add(app::add_run);
  add(app::add_check);
  add(app::add_backends);
  add(app::add_version);
  add(app::add_surface);
  add(app::add_contact);
  add(app::add_strength_table);
  add(app::add_dem);
  add(app::add_wearmap);
  add(app::add_merge);
  add(app::add_completion);
  add(app::add_studies);
  app::add_examples(app);

  if (const auto unknown = unknown_command(app, argc, argv)) {
    std::vector<std::string> names;
    for (const auto* sub : app.get_subcommands({})) names.push_back(sub->get_name());
    log::error("unknown command '{}'; the commands are: {} (wearscale --help)", *unknown, fmt::join(names, ", "));
    return exit_bad_input;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp&) {
    std::cout << app::help_of_every_command(app);
    return 0;
  } catch (const CLI::ParseError& e) {
    log::error("{}", app::parse_error_line(app, argc, argv, e));
    return exit_bad_input;
  }

  log::set_level(quiet ? log::Level::Quiet : verbose ? log::Level::Verbose : log::Level::Normal);
  // Under mpirun, a rank's share of its node's cores unless -j or OMP_NUM_THREADS says.
  if (threads == 0 && std::getenv("OMP_NUM_THREADS") == nullptr) threads = mpi::default_threads_per_rank();
  if (threads > 0) {
    omp_set_num_threads(threads);
    FFTPlanCache::global().set_threads(threads);
  }
  install_interrupt_handlers();
  ignore_output_signals();  // a closed stdout or `ulimit -f`: write errors reported (exit 2), not a death
  app::set_invocation(argc, argv);
  const std::string command = app.get_subcommands().empty() ? "" : app.get_subcommands().front()->get_name();
  if (mpi::size() > 1 && (command == "backends" || command == "version" || command == "completion" ||
                          command == "merge")) {
    // Only studies spread their work over ranks (the runner decides which:
    // the contact study in slabs; over the task farm the runs of a sweep, a
    // wear map's surfaces, the junction runs of nano/dem);
    // P copies of another command would print or write the same at once.
    // Refused on every rank before any work.
    if (mpi::is_root())
      log::error("wearscale {}: runs on one rank only ({} ranks started; under mpirun the studies' commands are "
                 "distributed: the contact study, a rough wear map, a nano/dem pipeline, and the runs of any [sweep]); "
                 "run it without mpirun",
                 command, mpi::size());
    every_rank_refused = true;
    return exit_bad_input;
  }
  // Under mpirun the ranks other than 0 print nothing (rank 0 speaks for the job), except their own failure.
  if (mpi::size() > 1 && !mpi::is_root()) log::set_level(log::Level::Silent);
  try {
    for (auto* sub : app.get_subcommands())
      if (commands.count(sub) != 0) {
        const int status = commands.at(sub)();
        // What a command printed reached standard output, or it says so (a closed pipe, a full disk under
        // `> file`): the files of a run are complete in its folder either way.
        std::cout.flush();
        if (status == 0 && !std::cout) {
          log::error("cannot write to standard output (closed, or its disk full): the results printed there are "
                     "lost; a run's files are complete in its output folder");
          return exit_bad_input;
        }
        return status;
      }
    return exit_bad_input;
  } catch (const Interrupted& e) {
    if (dynamic_cast<const mpi::JointInterruption*>(&e) != nullptr) every_rank_refused = true;  // all stopped alike
    log::error("{}", e.what());
    return exit_interrupted;
  } catch (const std::exception& e) {
    if (interrupt_requested()) {  // a failure caused by the stop, e.g. a child process killed by the same Ctrl-C
      log::error("interrupted by a signal ({})", e.what());
      return exit_interrupted;
    }
    if (const auto* failed = dynamic_cast<const mpi::TasksFailed*>(&e)) {  // every rank ends together
      every_rank_refused = true;
      if (failed->speaks()) log::error("{}", e.what());
      return failed->output() ? exit_bad_input : exit_numerical_failure;  // a full disk is 2, as a serial run's
    }
    if (const auto* joint = dynamic_cast<const mpi::JointRefusal*>(&e)) {  // every rank refused together
      every_rank_refused = true;
      if (joint->speaks()) {
        log::set_level(log::Level::Quiet);
        log::error("{}", e.what());
      }
      return exit_bad_input;
    }
    // A rank's own failure is heard, except a solver's NumericalError: the
    // solver's sums are the same on every rank, so every rank fails alike and
    // rank 0 says it once.
    if (mpi::size() > 1 && !mpi::is_root() && dynamic_cast<const NumericalError*>(&e) == nullptr)
      log::set_level(log::Level::Quiet);
    if (dynamic_cast<const InputError*>(&e) != nullptr) {
      log::error("{}", e.what());
      return exit_bad_input;
    }
    if (dynamic_cast<const NumericalError*>(&e) != nullptr) {
      log::error("{}", e.what());
      return exit_numerical_failure;
    }
    // The file system refused an operation no check anticipated (a folder
    // vanished, permissions changed under the run): bad environment, not a bug.
    if (const auto* fe = dynamic_cast<const std::filesystem::filesystem_error*>(&e)) {
      log::error("{}", fe->what());
      return exit_bad_input;
    }
    // Sizes are checked against the memory limit before a run allocates; this
    // is the last resort when the machine runs short anyway (other processes).
    if (dynamic_cast<const std::bad_alloc*>(&e) != nullptr) {
      log::error("out of memory: the run needs more memory than is free now (its sizes passed the check against "
                 "the machine's memory; other processes may be using it)");
      return exit_numerical_failure;
    }
    log::error("internal error: {}", e.what());
    return 3;
  }
}
}  // namespace
