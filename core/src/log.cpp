#include "wearscale/core/log.hpp"

#include <atomic>
#include <cstdio>
#include <mutex>

namespace wearscale::log {

namespace {
std::atomic<Level> current{Level::Normal};
std::mutex write_mutex;
std::atomic<bool> status_line{false};
}  // namespace

void set_status_line(bool drawn) { status_line = drawn; }

void set_level(Level l) { current = l; }
Level level() { return current; }

void write(Level at_least, std::string_view prefix, std::string_view message) {
  if (static_cast<int>(current.load()) < static_cast<int>(at_least)) return;
  std::lock_guard lock(write_mutex);
  if (status_line.exchange(false)) std::fputs("\r\033[K", stderr);  // the progress redraws on its next update
  std::fprintf(stderr, "%.*s%.*s\n", static_cast<int>(prefix.size()), prefix.data(), static_cast<int>(message.size()),
               message.data());
}

}  // namespace wearscale::log
