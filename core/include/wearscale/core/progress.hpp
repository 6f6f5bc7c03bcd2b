#pragma once
// Progress of a long computation: a one-line bar with rate and ETA on an
// interactive terminal; silent when stderr is not a TTY, when CI is set, or
// in quiet mode, so logs and CI output stay clean.
#include <chrono>
#include <string>

namespace wearscale {

class Progress {
 public:
  /// `total` units of work (steps, iterations, cases), named `unit`.
  Progress(std::string label, double total, std::string unit = "steps");
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// A reporter that never prints (for tests and nested work).
  static Progress silent(double total = 1.0);

  /// Reports `done` units finished (absolute, not an increment). Redraws at most ~5 times a second.
  void update(double done);
  /// Work done before this reporter started (a resumed run): counted as
  /// done, not in the rate.
  void start_at(double done);
  /// Clears the line; called by the destructor if needed.
  void finish();

  bool enabled() const { return enabled_; }
  double rate() const;          ///< units per second so far (0 before any progress)
  double eta_seconds() const;   ///< estimated seconds left (NaN before any progress)
  /// The line that would be drawn now, e.g. "pin-on-disc  42% 12.5 steps/s ETA 1m05s";
  /// rate and ETA read "--" until a unit of work has been done and half a
  /// second has passed (the first rate would otherwise include the setup).
  std::string line() const;

  /// `text` cut to at most `columns` characters (UTF-8 code points), so
  /// that a line never wraps on a narrow terminal.
  static std::string fit_to_width(const std::string& text, std::size_t columns);
  /// The width of the terminal on stderr (80 when it cannot be read).
  static std::size_t terminal_columns();

  /// Whether a new reporter would draw: stderr is a TTY, CI is unset and the log level is not quiet.
  static bool terminal_is_interactive();

 private:
  Progress(std::string label, double total, std::string unit, bool enabled);
  using clock = std::chrono::steady_clock;
  std::string label_, unit_;
  double total_, done_ = 0.0, base_ = 0.0;
  bool enabled_, drawn_ = false;
  clock::time_point start_, last_draw_;
};

}  // namespace wearscale
