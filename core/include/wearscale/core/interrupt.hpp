#pragma once
// A clean stop on SIGINT (Ctrl-C) or SIGTERM: the signal only raises a flag;
// solver loops look at it between steps, save their checkpoint and throw
// Interrupted, so unfinished files are removed and finished ones stay. A
// second signal while the first is being handled ends the process at once.
#include <string_view>

namespace wearscale {

/// Installs the handlers (once per process; the program calls it in main).
void install_interrupt_handlers();

/// Ignores SIGPIPE and SIGXFSZ, so that a closed standard output (`wearscale
/// ... | head`) or the file size limit (`ulimit -f`) is a failed write
/// (EPIPE, EFBIG) that the checked writes report, exit 2, with the unfinished
/// files removed, never a death by signal. The program calls it in main.
void ignore_output_signals();

/// Whether SIGINT or SIGTERM has arrived (or request_interrupt was called).
bool interrupt_requested();
/// The signal that arrived (SIGINT, SIGTERM), 0 if none.
int interrupt_signal();

/// Raises the flag as a signal would (tests, and code that wants to stop a run).
void request_interrupt(int signal_number);
/// Lowers the flag (tests only).
void clear_interrupt();

/// Throws Interrupted("<where>: interrupted by SIGINT") if a stop was requested.
void throw_if_interrupted(std::string_view where);

}  // namespace wearscale
