#include "wearscale/core/interrupt.hpp"

#include <csignal>

#include <atomic>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale {

namespace {
// Only lock-free atomics may be touched from a signal handler.
std::atomic<int> pending{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_signal(int sig) {
  if (pending.load() != 0) {  // a second signal: the user insists, stop now
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  pending.store(sig);
}
}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // system calls in flight (writes, waits) carry on
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

void ignore_output_signals() {
  struct sigaction action {};
  action.sa_handler = SIG_IGN;
  sigemptyset(&action.sa_mask);
  sigaction(SIGPIPE, &action, nullptr);
  sigaction(SIGXFSZ, &action, nullptr);
}

bool interrupt_requested() { return pending.load(std::memory_order_relaxed) != 0; }
int interrupt_signal() { return pending.load(); }
void request_interrupt(int signal_number) { pending.store(signal_number); }
void clear_interrupt() { pending.store(0); }

void throw_if_interrupted(std::string_view where) {
  const int sig = pending.load();
  if (sig == 0) return;
  const char* name = sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "a signal";
  throw Interrupted(fmt::format("{}: interrupted by {}", where, name));
}

}  // namespace wearscale
