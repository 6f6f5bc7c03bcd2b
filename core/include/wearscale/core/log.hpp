#pragma once
// Messages to the user on stderr (stdout is reserved for results and --json).
#include <cstdio>
#include <filesystem>
#include <string_view>
#include <utility>

#include <fmt/format.h>

namespace wearscale::log {

/// Silent: nothing at all, not even warnings and errors (the ranks other than 0 of an MPI job).
enum class Level { Silent = -1, Quiet = 0, Normal = 1, Verbose = 2 };

void set_level(Level level);
Level level();
void write(Level at_least, std::string_view prefix, std::string_view message);
/// A progress line is drawn on stderr (without a newline): the next message
/// clears it first, so that it starts on a clean line.
void set_status_line(bool drawn);

/// While one lives on a thread, that thread's messages (all but debug ones
/// unless verbose) also go to `file`, appended, whatever the level on stderr:
/// the log of one task of an ensemble (a run of a sweep) in its own folder,
/// written on every rank, the silent ones too. A file that cannot be opened
/// gets a warning and no log.
class TaskLog {
 public:
  explicit TaskLog(const std::filesystem::path& file);
  ~TaskLog();
  TaskLog(const TaskLog&) = delete;
  TaskLog& operator=(const TaskLog&) = delete;

 private:
  std::FILE* file_ = nullptr;
  std::FILE* previous_ = nullptr;
};

/// A line for this thread's task log only (nothing on stderr; nothing without a TaskLog).
void task_note(std::string_view message);

template <class... A>
void info(fmt::format_string<A...> f, A&&... a) { write(Level::Normal, "", fmt::format(f, std::forward<A>(a)...)); }
template <class... A>
void debug(fmt::format_string<A...> f, A&&... a) { write(Level::Verbose, "debug: ", fmt::format(f, std::forward<A>(a)...)); }
/// Warnings show even in quiet mode.
template <class... A>
void warn(fmt::format_string<A...> f, A&&... a) { write(Level::Quiet, "warning: ", fmt::format(f, std::forward<A>(a)...)); }
template <class... A>
void error(fmt::format_string<A...> f, A&&... a) { write(Level::Quiet, "error: ", fmt::format(f, std::forward<A>(a)...)); }

}  // namespace wearscale::log
