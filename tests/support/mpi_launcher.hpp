#pragma once
// The launcher of the MPI tests: `mpirun -np P` as CMake found it
// (WEARSCALE_MPIRUN: --allow-run-as-root --oversubscribe), for run_cli.
#include <string>

/// `mpirun … -np ranks`, or nothing for ranks = 0 (the program started on its own).
inline std::string mpi_launcher(int ranks) {
  return ranks == 0 ? std::string() : std::string(WEARSCALE_MPIRUN) + " -np " + std::to_string(ranks);
}

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <thread>

#include "cli_runner.hpp"

/// What became of an MPI job one of whose worker ranks was killed.
struct KilledJob {
  bool killed = false;  ///< a worker rank was found and sent SIGKILL
  int status = 0;       ///< the job's wait status
};

/// Starts `wearscale args` under `mpirun -np ranks` in `cwd` (one thread a
/// rank, output to killed.out/err there), waits (up to 120 s: a loaded CI
/// machine sets a DEM cell up slowly) until `ready()`,
/// then kills (SIGKILL) one worker rank: a wearscale process of the job whose
/// OMPI_COMM_WORLD_RANK is not 0 (the job is found by `marker`, a word of its
/// command line such as its output folder); returns once the job has ended.
inline KilledJob kill_a_worker_rank(const std::string& cwd, int ranks, const std::string& args,
                                    const std::string& marker, const std::function<bool()>& ready) {
  const std::string cmd = "cd '" + cwd + "' && exec env CI=true OMP_NUM_THREADS=1 " WEARSCALE_MPIRUN " -np " +
                          std::to_string(ranks) + " '" + std::string(WEARSCALE_CLI) + "' " + args +
                          " >killed.out 2>killed.err";
  KilledJob out;
  const pid_t job = spawn_shell(cmd);
  if (job < 0) return out;
  for (int wait = 0; wait < 2400 && !out.killed; ++wait) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (!ready()) continue;
    const std::string find = "for p in $(pgrep -f -- '" + marker + "'); do "
                             "tr '\\0' '\\n' </proc/$p/environ 2>/dev/null | grep -qx 'OMPI_COMM_WORLD_RANK=[1-9]' "
                             "&& echo $p; done";
    FILE* pipe = ::popen(find.c_str(), "r");
    char line[64] = {};
    const bool got = pipe != nullptr && std::fgets(line, sizeof line, pipe) != nullptr;
    if (pipe != nullptr) ::pclose(pipe);
    if (got && std::atoi(line) > 0) out.killed = ::kill(std::atoi(line), SIGKILL) == 0;
  }
  ::waitpid(job, &out.status, 0);
  return out;
}
