#pragma once
// The kinds of failure a user can meet, and the exit status of each
// (docs/reliability.md).
#include <stdexcept>
#include <string>

namespace wearscale {

inline constexpr int exit_success = 0;
inline constexpr int exit_numerical_failure = 1;
inline constexpr int exit_bad_input = 2;
/// Stopped by SIGINT or SIGTERM after saving a checkpoint and removing
/// unfinished files (128 + SIGINT, the shell's convention).
inline constexpr int exit_interrupted = 130;

/// Bad input: a missing file, a syntax error, an unknown key, a value of the
/// wrong type or out of its allowed range. The message names what and where.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}

  /// "<file>: key 'a.b' = <value>: <problem>; allowed: <allowed>"
  static InputError at_key(const std::string& file, const std::string& key,
                           const std::string& value, const std::string& problem,
                           const std::string& allowed);
};

/// An output that cannot be written: a folder that cannot be created or is
/// read-only, a full disk, a folder another run is writing into. The
/// message names the path and the cause; nothing is left under a final name.
/// Exit status 2, as bad input: the user can act on it (another --out, free
/// space) and resume.
class OutputError : public InputError {
 public:
  explicit OutputError(const std::string& message) : InputError(message) {}
};

/// A numerical failure: divergence, NaN/Inf, an unstable time step. The
/// message names the solver, the step (or iteration) and the quantity.
class NumericalError : public std::runtime_error {
 public:
  NumericalError(const std::string& solver, long step, const std::string& quantity,
                 const std::string& detail);
  const std::string& solver() const { return solver_; }
  long step() const { return step_; }
  const std::string& quantity() const { return quantity_; }
  const std::string& detail() const { return detail_; }

 private:
  std::string solver_;
  long step_;
  std::string quantity_, detail_;
};

/// The run was asked to stop (SIGINT/SIGTERM): thrown from a solver loop
/// after its checkpoint is saved, so that every unfinished output is removed
/// on the way out. The program then exits with exit_interrupted.
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace wearscale
