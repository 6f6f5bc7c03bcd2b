#pragma once
// The two kinds of failure a user can meet, and the exit status of each.
#include <stdexcept>
#include <string>

namespace wearscale {

inline constexpr int exit_success = 0;
inline constexpr int exit_numerical_failure = 1;
inline constexpr int exit_bad_input = 2;

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

/// A numerical failure: divergence, NaN/Inf, an unstable time step. The
/// message names the solver, the step (or iteration) and the quantity.
class NumericalError : public std::runtime_error {
 public:
  NumericalError(const std::string& solver, long step, const std::string& quantity,
                 const std::string& detail);
  const std::string& solver() const { return solver_; }
  long step() const { return step_; }

 private:
  std::string solver_;
  long step_;
};

}  // namespace wearscale
