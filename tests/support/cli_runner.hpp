#pragma once
// Runs the wearscale program as a user would and captures what it prints.
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

struct CliResult {
  int status;
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::stringstream ss;
  ss << std::ifstream(p).rdbuf();
  return ss.str();
}

/// `args` is passed through the shell; run from `cwd`. CI is set so no
/// progress bar is drawn; `env` adds variables ("WEARSCALE_MEMORY_LIMIT=8GiB");
/// `launcher` starts the program ("mpirun -np 3", see mpi_launcher.hpp).
inline CliResult run_cli(const std::string& args, const std::filesystem::path& cwd, const std::string& env = {},
                         const std::string& launcher = {}) {
  std::filesystem::create_directories(cwd);
  const auto out = cwd / "cli.stdout", err = cwd / "cli.stderr";
  const std::string cmd = "cd '" + cwd.string() + "' && CI=true " + env + " " + launcher + " '" +
                          std::string(WEARSCALE_CLI) + "' " + args + " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int raw = std::system(cmd.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
}

/// Starts `cmd` through /bin/sh in the background and returns its pid (or a
/// negative value when no process could be made); the caller waits for it.
inline pid_t spawn_shell(const std::string& cmd) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}
