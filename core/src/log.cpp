#include "wearscale/core/log.hpp"

#include <atomic>
#include <cstdio>
#include <mutex>

namespace wearscale::log {

namespace {
std::atomic<Level> current{Level::Normal};
std::mutex write_mutex;
std::atomic<bool> status_line{false};
thread_local std::FILE* task_file = nullptr;  // this thread's TaskLog, if any
}  // namespace

TaskLog::TaskLog(const std::filesystem::path& file) : previous_(task_file) {
  file_ = std::fopen(file.c_str(), "a");
  if (file_ == nullptr) {
    write(Level::Quiet, "warning: ", "cannot open the task log " + file.string() + "; this task's messages go to stderr only");
    return;
  }
  task_file = file_;
}

TaskLog::~TaskLog() {
  if (file_ == nullptr) return;
  task_file = previous_;
  std::fclose(file_);
}

void set_status_line(bool drawn) { status_line = drawn; }

void set_level(Level l) { current = l; }
Level level() { return current; }

void task_note(std::string_view message) {
  if (task_file == nullptr) return;
  std::fprintf(task_file, "%.*s\n", static_cast<int>(message.size()), message.data());
  std::fflush(task_file);
}

void write(Level at_least, std::string_view prefix, std::string_view message) {
  if (task_file != nullptr && (at_least != Level::Verbose || current.load() == Level::Verbose)) {
    std::fprintf(task_file, "%.*s%.*s\n", static_cast<int>(prefix.size()), prefix.data(),
                 static_cast<int>(message.size()), message.data());
    std::fflush(task_file);
  }
  if (static_cast<int>(current.load()) < static_cast<int>(at_least)) return;
  std::lock_guard lock(write_mutex);
  if (status_line.exchange(false)) std::fputs("\r\033[K", stderr);  // the progress redraws on its next update
  std::fprintf(stderr, "%.*s%.*s\n", static_cast<int>(prefix.size()), prefix.data(), static_cast<int>(message.size()),
               message.data());
}

}  // namespace wearscale::log
