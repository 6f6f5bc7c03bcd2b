#include "hdf5_lock.hpp"
#include "wearscale/core/hdf5_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <functional>
#include <string>

#include <new>

#include <fmt/format.h>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define WEARSCALE_HAS_SANITIZER 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define WEARSCALE_HAS_SANITIZER 1
#endif
#ifdef WEARSCALE_HAS_SANITIZER
#include <sanitizer/common_interface_defs.h>
#endif

namespace wearscale::detail {

namespace {

bool& in_trial_child() {
  static bool flag = false;
  return flag;
}

double now() {
  timespec t{};
  ::clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

[[noreturn]] void trial(const std::function<void()>& read) {
  // A crash here is the verdict, not a report: the default actions, no
  // sanitizer report or fuzzer artifact, no output.
  for (int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) ::signal(s, SIG_DFL);
#ifdef WEARSCALE_HAS_SANITIZER
  __sanitizer_set_death_callback(nullptr);
#endif
  if (const int null = ::open("/dev/null", O_WRONLY); null >= 0) ::dup2(null, 2);
  // The only thread left: the lock held by the parent's thread is made anew.
  new (&hdf5_mutex()) std::recursive_mutex();
  in_trial_child() = true;
  try {
    read();
  } catch (...) {  // the parent meets the same error in-process, and reports it
  }
  ::_exit(0);  // no destructors, no leak check: the parent goes on
}

}  // namespace

std::recursive_mutex& hdf5_mutex() {
  static std::recursive_mutex m;
  return m;
}

std::string try_in_child(const std::function<void()>& read, double timeout_seconds) {
  if (in_trial_child()) return {};  // already the trial: read on
  pid_t pid = -1;
  {
    // No other thread is inside HDF5 while the child is made: it starts from a consistent library.
    std::lock_guard lock(hdf5_mutex());
    pid = ::fork();
    if (pid == 0) trial(read);  // never returns
  }
  if (pid < 0) return {};  // no child possible (process limits): read in-process as before
  const double deadline = now() + timeout_seconds;
  int status = 0;
  for (;;) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) return {};
    if (now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      return fmt::format("the HDF5 library did not finish reading it within {:.0f} s", timeout_seconds);
    }
    const timespec pause{0, 500000};
    ::nanosleep(&pause, nullptr);
  }
  if (WIFSIGNALED(status))
    return fmt::format("the HDF5 library crashed reading it (signal {}, {})", WTERMSIG(status),
                       ::strsignal(WTERMSIG(status)));
  if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
    return fmt::format("the HDF5 library failed reading it (exit status {})", WEXITSTATUS(status));
  return {};
}

}  // namespace wearscale::detail
