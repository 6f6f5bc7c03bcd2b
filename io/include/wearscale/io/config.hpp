#pragma once
// Case files: TOML with typed, range-checked getters.
//
// Every value a program reads goes through a getter that states its type,
// allowed range and physical dimension; a bad value raises InputError naming
// the file (and line), the key, the value and what is allowed. Keys that no
// component read are errors too (reject_unknown_keys), so a typo never falls
// back silently to a default.
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/range.hpp"
#include "wearscale/core/units.hpp"

namespace wearscale {

/// Thrown by Config::reject_unknown_keys() on the whole case when a check
/// asked to stop there (stop_when_checked): every key has been read and
/// found valid, and nothing of the run has started. Not an error.
struct CaseChecked {};

class Config {
 public:
  /// Reads and parses a TOML file; InputError if it is missing, not a
  /// regular file, larger than max_case_file_bytes, or malformed.
  static Config load(const std::filesystem::path& file);
  static constexpr std::uintmax_t max_case_file_bytes = std::uintmax_t{4} << 20;
  /// Bounds on a case's shape, checked when it is parsed (and on every --set key): tables,
  /// arrays and inline tables nested at most max_depth deep, every dotted key at most
  /// max_key_bytes long. A deeper or longer case is no case wearscale reads, and walking
  /// one costs time that grows with the cube of its depth.
  static constexpr std::size_t max_depth = 32;
  static constexpr std::size_t max_key_bytes = 1024;
  /// Parses TOML text; `source` names it in error messages.
  static Config from_string(std::string_view text, std::string source = "<string>");

  /// Applies a command-line override "KEY=VALUE" (`--set`). VALUE is read as
  /// TOML (number, bool, "string", [array], {inline = table}); a bare word is
  /// taken as a string. Intermediate tables are created as needed. A value
  /// of several lines is refused (a second line would be dropped). `origin`
  /// names where the value came from in messages ("--set", or the sweep
  /// value of a case file: "case.toml:12 (sweep.values[1])").
  void override_value(std::string_view assignment, std::string_view origin = "--set");

  /// An independent copy of the whole case (its values, overrides and the keys read so far); a
  /// copy made by the copy constructor is a view of the same case instead.
  Config clone() const;
  /// Removes a key or table (and everything under it) from the case; nothing if it is absent.
  void erase(std::string_view key);

  /// A view of a sub-table; its keys are relative to `key`. An absent table
  /// gives an empty view (every optional getter then returns its fallback).
  Config section(std::string_view key) const;
  bool has(std::string_view key) const;
  /// Names of the entries of a table (e.g. the materials a case defines).
  std::vector<std::string> keys(std::string_view table = {}) const;

  // --- Typed getters; `key` is dotted and relative to this view ------------
  /// A number: TOML float or integer, or a string with a unit ("8 mm/s") whose
  /// dimension must be `dim`. Returned in SI.
  double number(std::string_view key, const Range& range = {},
                units::Dimension dim = units::dimensionless) const;
  double number_or(std::string_view key, double fallback, const Range& range = {},
                   units::Dimension dim = units::dimensionless) const;
  long integer(std::string_view key, const Range& range = {}) const;
  long integer_or(std::string_view key, long fallback, const Range& range = {}) const;
  bool boolean(std::string_view key) const;
  bool boolean_or(std::string_view key, bool fallback) const;
  std::string string(std::string_view key) const;
  std::string string_or(std::string_view key, std::string fallback) const;
  /// A string that must be one of `allowed`.
  std::string choice(std::string_view key, std::initializer_list<std::string_view> allowed) const;
  std::string choice_or(std::string_view key, std::string fallback,
                        std::initializer_list<std::string_view> allowed) const;
  std::string choice(std::string_view key, const std::vector<std::string>& allowed) const;
  std::string choice_or(std::string_view key, std::string fallback, const std::vector<std::string>& allowed) const;
  /// A file name: a non-empty string; relative names in a case file are
  /// relative to the folder of that file, on the command line (--set) to the
  /// working directory.
  std::filesystem::path path(std::string_view key) const;
  std::vector<double> numbers(std::string_view key, const Range& range = {},
                              units::Dimension dim = units::dimensionless) const;
  /// The physical dimension a number getter (number(), number_or() when
  /// present, numbers()) read `key` in, once one has: what its values mean
  /// in SI (a sweep table's unit for a swept key); nullopt before.
  std::optional<units::Dimension> dimension_of(std::string_view key) const;
  /// The elements of an array as override text: numbers in full precision,
  /// strings as written ("inf", "1 um"). For sweeps over any key.
  std::vector<std::string> values_as_text(std::string_view key) const;

  /// Marks a key (and everything under it) as read without reading it.
  void mark_used(std::string_view key) const;
  /// Every key read so far (by a getter or mark_used), as full dotted keys.
  std::vector<std::string> keys_read() const;
  /// InputError for the keys nobody read (every one of them, with the keys
  /// read in the same table and the closest: "did you mean …?"). On the
  /// whole case (a view without prefix) it is the point where every key has
  /// been read: the errors collected until then (collect_errors) are raised
  /// with the unknown keys as one InputError, and collecting stops.
  void reject_unknown_keys() const;

  // --- Every error of a case at once ---------------------------------------
  /// While on, the getters record the errors that do not depend on each other
  /// instead of throwing at the first: a value out of range, of the wrong
  /// type or unit, or not a known choice, of a key that has a default (the
  /// default stands in for it) or of a required number or integer (its
  /// nearest allowed value stands in). A missing required key, or a check
  /// between keys, still throws, after the errors recorded before it.
  /// Shared by the copies and views of this case.
  void collect_errors(bool on) const;
  /// Throws the recorded errors as one InputError (one error: its own
  /// message; several: a numbered list), then stops collecting.
  void raise_collected_errors() const;
  /// The recorded errors and `last` (an error thrown while collecting,
  /// which may follow from the values that stood in for the others) as one.
  [[nodiscard]] InputError collected_with(const std::string& last) const;
  bool has_collected_errors() const;
  /// Whether reject_unknown_keys() has passed on the whole case.
  bool fully_checked() const;
  /// When on, reject_unknown_keys() on the whole case throws CaseChecked once
  /// it passes (a check that must not go on into the work).
  void stop_when_checked(bool on) const;
  /// Every default a getter applied to an absent key, {dotted key: value}.
  const nlohmann::json& applied_defaults() const;
  /// The resolved case with the applied defaults added where absent.
  nlohmann::json to_json_with_defaults() const;

  /// The InputError for a value found invalid after it was read, e.g. by a
  /// consistency check between two keys; names file, line, key and value.
  [[nodiscard]] InputError error(std::string_view key, std::string_view problem,
                                 std::string_view allowed = {}) const;

  const std::string& source() const;
  /// Where a key's value comes from: "case.toml:12", or the origin of its override.
  std::string where(std::string_view key) const;
  /// Absolute dotted key of a key of this view.
  std::string full_key(std::string_view key) const;
  /// The resolved case (overrides applied) as JSON and as TOML text.
  nlohmann::json to_json() const;
  std::string to_toml() const;

  Config(const Config&);
  Config& operator=(const Config&);
  Config(Config&&) noexcept;
  Config& operator=(Config&&) noexcept;
  ~Config();

 private:
  struct State;
  Config(std::shared_ptr<State> state, std::string prefix);
  /// Records `e` and returns true while collecting; false otherwise (the caller throws it).
  bool record(const InputError& e) const;
  void record_default(std::string_view key, nlohmann::json value) const;
  std::shared_ptr<State> state_;
  std::string prefix_;
};

}  // namespace wearscale
