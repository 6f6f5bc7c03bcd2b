// The pre-initialisation that chooses how OpenMP threads wait
// (thread_waiting.hpp). Linked into executables only: a shared object may
// not have a .preinit_array.
#include <unistd.h>

#include <cstddef>
#include <cstring>
#include <iterator>

#include "wearscale/core/thread_waiting.hpp"

namespace {
bool names(const char* entry, const char* name) {
  const std::size_t n = std::strlen(name);
  return std::strncmp(entry, name, n) == 0 && entry[n] == '=';
}

// "NAME=value" into `out`, which holds it (sized by the caller at compile time).
char* entry(char* out, const char* name, const char* value) {
  std::strcpy(out, name);
  std::strcat(out, "=");
  return std::strcat(out, value);
}

// Runs before any library is initialised, the C library's included: the
// environment is read from `envp` (getenv and setenv do not work yet), and a
// variable could not be set for libgomp anyway (the C library's
// initialisation takes the environment the process was started with). So
// the program starts itself again with the variable added, before anything
// is open or written; if that fails (no /proc), it goes on with the
// runtime's default.
void choose_thread_waiting(int, char** argv, char** envp) {
  if (argv == nullptr || envp == nullptr) return;
  static char* env[4096];  // no allocator is ready yet; a larger environment keeps the default
  std::size_t count = 0;
  for (; envp[count] != nullptr; ++count)
    if (count + 3 > std::size(env) || names(envp[count], "OMP_WAIT_POLICY") || names(envp[count], "GOMP_SPINCOUNT"))
      return;
  static char spin_count[sizeof "GOMP_SPINCOUNT=" + sizeof wearscale::waiting_spin_count];
  static char marker[sizeof wearscale::detail::thread_waiting_marker + sizeof "=1"];
  for (std::size_t k = 0; k < count; ++k) env[k] = envp[k];
  env[count] = entry(spin_count, "GOMP_SPINCOUNT", wearscale::waiting_spin_count);
  env[count + 1] = entry(marker, wearscale::detail::thread_waiting_marker, "1");  // what thread_waiting() reads
  env[count + 2] = nullptr;
  // The program's own path (not /proc/self/exe, whose name would become
  // the process's: `ps` and `killall wearscale` would see "exe").
  static char self[4096];
  const ssize_t length = ::readlink("/proc/self/exe", self, sizeof self - 1);
  if (length <= 0) return;
  self[length] = '\0';
  ::execve(self, argv, env);
}
}  // namespace

__attribute__((section(".preinit_array"), used)) static void (*const wearscale_thread_waiting)(int, char**, char**) =
    choose_thread_waiting;
