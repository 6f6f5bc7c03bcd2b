#pragma once
// Messages to the user on stderr (stdout is reserved for results and --json).
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
