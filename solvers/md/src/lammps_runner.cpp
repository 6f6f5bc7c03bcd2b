#include "wearscale/md/lammps_runner.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>
#include <thread>

#include <fmt/format.h>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/program_path.hpp"
#include "wearscale/core/sha256.hpp"

extern "C" char** environ;

namespace wearscale::md {

namespace fs = std::filesystem;

namespace {

constexpr const char* kInstall = "apt-get install lammps";

struct Child {
  pid_t pid = -1;
};

bool starts_with_any(std::string_view entry, std::initializer_list<std::string_view> prefixes) {
  for (auto p : prefixes)
    if (entry.substr(0, p.size()) == p) return true;
  return false;
}

}  // namespace

bool is_mpi_rank() {
  // The variables a launcher gives its ranks: Open MPI's mpirun, PMI (MPICH, Intel MPI), PMIx (srun).
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK"})
    if (std::getenv(v) != nullptr) return true;
  return false;
}

std::vector<std::string> child_environment() {
  std::vector<std::string> env;
  const bool nested = is_mpi_rank();
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string_view entry(*e);
    // A rank's launcher variables would make lmp (MPI_Init) or a nested mpirun
    // join the enclosing job instead of starting one of their own; Slurm's
    // would make that mpirun launch through the enclosing step's srun.
    if (nested && starts_with_any(entry, {"OMPI_", "PMIX_", "PMI_", "SLURM_", "HYDRA_", "MPIR_", "I_MPI_", "MPI_LOCALRANKID",
                                          "MPI_LOCALNRANKS"}))
      continue;
    env.emplace_back(entry);
  }
  return env;
}

namespace {

// fork + exec of argv in `cwd`, stdout and stderr to `out` (created or
// truncated). Only async-signal-safe calls between fork and exec.
Child spawn(const std::vector<std::string>& argv, const fs::path& cwd, const fs::path& out) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const std::vector<std::string> environment = child_environment();
  std::vector<char*> envp;
  for (const auto& e : environment) envp.push_back(const_cast<char*>(e.c_str()));
  envp.push_back(nullptr);
  // Absolute: the child changes to `cwd` before it opens `out` (a relative
  // cache folder, md.cache_dir = "cache", would otherwise name a file that is not there).
  const std::string dir = fs::absolute(cwd).string(), file = fs::absolute(out).string();
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(fmt::format("fork failed: {}", std::strerror(errno)));
  if (pid == 0) {
    // lmp (or mpirun, which passes it on to its ranks) ends when wearscale does.
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    // wearscale ignores SIGPIPE (write errors are reported instead); lmp and mpirun get the default back.
    struct sigaction default_action {};
    default_action.sa_handler = SIG_DFL;
    ::sigaction(SIGPIPE, &default_action, nullptr);
    if (::getppid() == 1) ::_exit(126);
    if (::chdir(dir.c_str()) != 0) ::_exit(126);
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) ::_exit(126);
    ::dup2(fd, STDOUT_FILENO);
    ::dup2(fd, STDERR_FILENO);
    ::close(fd);
    const int null_in = ::open("/dev/null", O_RDONLY);
    if (null_in >= 0) {
      ::dup2(null_in, STDIN_FILENO);
      ::close(null_in);
    }
    ::execve(args[0], args.data(), envp.data());
    ::_exit(127);
  }
  return {pid};
}

// Waits for the child, calling `poll` every 250 ms; returns the wait status.
int wait_for(Child c, const std::function<void()>& poll) {
  int status = 0;
  for (;;) {
    const pid_t r = ::waitpid(c.pid, &status, poll ? WNOHANG : 0);
    if (r == c.pid) return status;
    if (r < 0 && errno != EINTR) throw std::runtime_error(fmt::format("waitpid failed: {}", std::strerror(errno)));
    if (poll && r == 0) {
      poll();
      std::this_thread::sleep_for(std::chrono::milliseconds(250));
    }
  }
}

std::string describe_status(int status) {
  if (WIFEXITED(status)) return fmt::format("exit status {}", WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return fmt::format("killed by signal {}", WTERMSIG(status));
  return "abnormal end";
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Last "Step"-table step number printed in the log (for error messages), or -1.
long last_thermo_step(const fs::path& log) {
  std::ifstream in(log);
  std::string line;
  long last = -1;
  bool in_table = false;
  while (std::getline(in, line)) {
    if (line.rfind("   Step", 0) == 0 || line.rfind("Step", 0) == 0) {
      in_table = true;
      continue;
    }
    if (line.rfind("Loop time", 0) == 0) in_table = false;
    if (in_table) {
      char* end = nullptr;
      const long s = std::strtol(line.c_str(), &end, 10);
      if (end != line.c_str()) last = s;
    }
  }
  return last;
}

}  // namespace

fs::path find_lmp(const std::string& requested) {
  const std::string name = requested.empty() ? std::string("lmp") : requested;
  if (name.find('/') != std::string::npos) {
    if (is_executable_file(name)) return fs::absolute(name);
    throw InputError(fmt::format("LAMMPS executable '{}' not found or not executable; install LAMMPS with: {} "
                                 "(Debian 12), or give its path with --lmp / md.lmp",
                                 name, kInstall));
  }
  fs::path found = find_on_path(name);
  if (found.empty())
    throw InputError(fmt::format("LAMMPS executable '{}' not found on PATH; install LAMMPS with: {} (Debian 12), "
                                 "or give its path with --lmp / md.lmp",
                                 name, kInstall));
  return found;
}

std::string lammps_version(const fs::path& lmp, const fs::path& cache_dir) {
  std::error_code ec;
  const auto size = fs::file_size(lmp, ec);
  const auto mtime = fs::last_write_time(lmp, ec).time_since_epoch().count();
  const std::string id = sha256_hex(fmt::format("{}|{}|{}", fs::weakly_canonical(lmp, ec).string(), size, mtime));
  const fs::path remembered = cache_dir / "lmp-version" / (id + ".txt");
  if (fs::is_regular_file(remembered, ec)) {
    std::string v = slurp(remembered);
    while (!v.empty() && (v.back() == '\n' || v.back() == '\r')) v.pop_back();
    if (!v.empty()) return v;
  }
  const fs::path tmp = fs::temp_directory_path() / fmt::format("wearscale-lmp-h-{}", ::getpid());
  fs::create_directories(tmp, ec);
  const fs::path out = tmp / "lmp-h.txt";
  const int status = wait_for(spawn({lmp.string(), "-h"}, tmp, out), {});
  const std::string text = slurp(out);
  fs::remove_all(tmp, ec);
  std::string version;
  std::stringstream ss(text);
  std::string line;
  while (std::getline(ss, line)) {
    constexpr std::string_view sim = "Massively Parallel Simulator - ";
    if (auto p = line.find(sim); p != std::string::npos) {
      version = line.substr(p + sim.size());
      break;
    }
    if (line.rfind("LAMMPS (", 0) == 0) {
      version = line.substr(8, line.find(')') == std::string::npos ? std::string::npos : line.find(')') - 8);
      break;
    }
  }
  while (!version.empty() && (version.back() == ' ' || version.back() == '\r')) version.pop_back();
  if (version.empty())
    throw NumericalError("LAMMPS", 0, "version",
                         fmt::format("'{} -h' ({}) printed no LAMMPS version line; is it LAMMPS? ({})", lmp.string(),
                                     describe_status(status), kInstall));
  fs::create_directories(remembered.parent_path(), ec);
  if (!ec) {
    try {
      write_file_atomically(remembered, version + "\n");
    } catch (const std::exception&) {
      // a read-only cache only costs an `lmp -h` next time
    }
  }
  return version;
}

std::vector<std::string> lammps_command(const LammpsJob& job, int& ranks_used) {
  std::vector<std::string> cmd;
  ranks_used = 1;
  if (job.ranks > 1) {
    const fs::path mpirun = find_on_path("mpirun");
    if (!mpirun.empty()) {
      // --allow-run-as-root: Open MPI refuses root otherwise (containers, CI).
      // A rank waiting for a message yields its core: lmp's ranks often share
      // cores with other work (busy polling on 2 shared cores made a 379-step
      // Si point take 146-258 s instead of 0.7-3 s here); on cores of their
      // own it costs nothing measurable.
      cmd = {mpirun.string(), "--allow-run-as-root", "-np", std::to_string(job.ranks), "--mca", "mpi_yield_when_idle",
             "1"};
      // From a rank of an MPI job (wearscale under mpirun/srun): the job's
      // launcher placed this rank on cores of its own (inherited by mpirun and
      // lmp); several of these launches share a node, so none binds lmp's ranks
      // to cores of its choosing, and none refuses for want of slots.
      if (is_mpi_rank()) cmd.insert(cmd.end(), {"--bind-to", "none", "--oversubscribe"});
      ranks_used = job.ranks;
    }
  }
  cmd.insert(cmd.end(), {job.lmp.string(), "-in", job.input, "-log", "log.lammps", "-nocite"});
  return cmd;
}

std::string lammps_error_line(const fs::path& run_dir) {
  for (const char* name : {"stdout.txt", "log.lammps"}) {
    std::ifstream in(run_dir / name);
    std::string line;
    while (std::getline(in, line)) {
      // "ERROR: ..." or "ERROR on proc N: ..." (LAMMPS' error and error->one)
      if (line.find("ERROR:") != std::string::npos || line.find("ERROR on proc") != std::string::npos) return line;
    }
  }
  return {};
}

LammpsRunInfo run_lammps(const LammpsJob& job, const std::function<void()>& poll) {
  LammpsRunInfo info;
  info.command = lammps_command(job, info.ranks);
  const auto t0 = std::chrono::steady_clock::now();
  int status = 0;
  try {
    status = wait_for(spawn(info.command, job.run_dir, job.run_dir / "stdout.txt"), poll);
  } catch (const std::runtime_error& e) {
    throw NumericalError("LAMMPS", 0, "subprocess", fmt::format("{} in {}: {}", job.label, job.run_dir.string(), e.what()));
  }
  info.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::string error = lammps_error_line(job.run_dir);
  const bool failed = !(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  if (failed || !error.empty()) {
    std::string why = error;
    if (why.empty() && WIFEXITED(status) && WEXITSTATUS(status) == 127) why = fmt::format("could not execute {}", info.command[0]);
    if (why.empty()) why = "no ERROR line; see stdout.txt";
    throw NumericalError("LAMMPS", last_thermo_step(job.run_dir / "log.lammps"), job.label,
                         fmt::format("lmp failed ({}) in run folder {}: {}", describe_status(status),
                                     job.run_dir.string(), why));
  }
  return info;
}

}  // namespace wearscale::md
