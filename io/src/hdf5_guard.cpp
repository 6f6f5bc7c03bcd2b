#include "hdf5_lock.hpp"
#include "wearscale/io/hdf5_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <functional>
#include <string>

#include <new>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/memory_limit.hpp"

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

constexpr int kOutOfMemory = 3;  // the child's exit status when the read ran out of memory
constexpr int kInputError = 4;   // ... when it raised InputError (its message on the pipe)

bool& in_trial_child() {
  static bool flag = false;
  return flag;
}

double now() {
  timespec t{};
  ::clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

[[noreturn]] void trial(const std::function<void()>& read, int report) {
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
  // No memory bound here (RLIMIT_DATA): HDF5 meets a failed allocation with
  // an error that some calls (H5Lexists) turn into a plain "no", so a bounded
  // child would pass a file that then takes the parent's memory. A file that
  // makes HDF5 allocate without end meets the timeout instead.
  try {
    read();
  } catch (const std::bad_alloc&) {
    ::_exit(kOutOfMemory);  // beyond the bound: the parent must not try it in-process
  } catch (const InputError& e) {
    // The parent reports this error without reading the file itself: a read that failed here
    // (perhaps at the memory bound) is never repeated without the bound.
    const std::string_view what(e.what());
    const auto n = std::min<std::size_t>(what.size(), 16000);  // within the pipe's buffer
    for (std::size_t done = 0; done < n;) {
      const ssize_t w = ::write(report, what.data() + done, n - done);
      if (w <= 0) break;
      done += static_cast<std::size_t>(w);
    }
    ::_exit(kInputError);
  } catch (...) {  // the parent meets the same error in-process, and reports it
  }
  ::_exit(0);  // no destructors, no leak check: the parent goes on
}

}  // namespace

std::recursive_mutex& hdf5_mutex() {
  static std::recursive_mutex m;
  return m;
}

Trial try_in_child(const std::function<void()>& read, double timeout_seconds) {
  if (in_trial_child()) return {};  // already the trial: read on
  int report[2] = {-1, -1};
  if (::pipe2(report, O_CLOEXEC) != 0) return {};  // no pipe (descriptor limits): read in-process as before
  pid_t pid = -1;
  {
    // No other thread is inside HDF5 while the child is made: it starts from a consistent library.
    std::lock_guard lock(hdf5_mutex());
    pid = ::fork();
    if (pid == 0) {
      ::close(report[0]);
      trial(read, report[1]);  // never returns
    }
  }
  ::close(report[1]);
  const auto message = [&] {
    std::string text;
    char buffer[4096];
    for (ssize_t n; (n = ::read(report[0], buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<std::size_t>(n));
    ::close(report[0]);
    return text;
  };
  if (pid < 0) {
    ::close(report[0]);
    return {};  // no child possible (process limits): read in-process as before
  }
  const double deadline = now() + timeout_seconds;
  int status = 0;
  for (;;) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) {
      ::close(report[0]);
      return {};
    }
    if (now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      ::close(report[0]);
      return {fmt::format("the HDF5 library did not finish reading it within {:.0f} s", timeout_seconds), {}};
    }
    const timespec pause{0, 500000};
    ::nanosleep(&pause, nullptr);
  }
  std::string error = message();
  if (WIFSIGNALED(status))
    return {fmt::format("the HDF5 library crashed reading it (signal {}, {})", WTERMSIG(status),
                        ::strsignal(WTERMSIG(status))),
            {}};
  if (WIFEXITED(status) && WEXITSTATUS(status) == kOutOfMemory)
    return {fmt::format("reading it needs more memory than this process may use ({}, {})", format_bytes(memory_limit().bytes),
                        memory_limit().source),
            {}};
  if (WIFEXITED(status) && WEXITSTATUS(status) == kInputError && !error.empty()) return {{}, std::move(error)};
  if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
    return {fmt::format("the HDF5 library failed reading it (exit status {})", WEXITSTATUS(status)), {}};
  return {};
}

}  // namespace wearscale::detail
