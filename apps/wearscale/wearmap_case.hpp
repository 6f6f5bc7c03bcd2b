#pragma once
// A wear-map case: the [wearmap.<kind>] table of a TOML case file, the
// command-line flags that map onto its keys (a flag overrides the file), the
// `--set KEY=VALUE` overrides (which override both) and the [output] dir.
#include <deque>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "wearscale/core/config.hpp"
#include "wearscale/core/output_lock.hpp"

namespace wearscale::app {

struct WearmapCase {
  struct Flag {
    std::string name, key, value;  ///< e.g. "--hurst", "wearmap.rough.hurst", the text given (empty: not given)
    bool range = false;            ///< a "MIN:MAX" flag written to the key as [MIN, MAX]
  };
  std::string case_file, out;
  std::deque<Flag> flags;  ///< a deque: CLI11 keeps pointers to the values
  std::vector<std::string> overrides;
  bool json = false;
};

/// The positional CASE, --set, --out and --json; `table` names the case table in the help.
void add_case_options(CLI::App* cmd, WearmapCase& c, const std::string& table);
/// `--name VALUE` writing the case key `key`.
CLI::Option* add_case_flag(CLI::App* cmd, WearmapCase& c, const std::string& name, const std::string& key,
                   const std::string& help);
/// `--name MIN:MAX` writing the case key `key` as [MIN, MAX].
void add_case_range_flag(CLI::App* cmd, WearmapCase& c, const std::string& name, const std::string& key,
                         const std::string& help);
/// `--name` (no value) writing `key = value`.
void add_case_switch(CLI::App* cmd, WearmapCase& c, const std::string& name, const std::string& key,
                     const std::string& value, const std::string& help);

/// The case file, then the flags, then --set, as one Config.
Config build_case(const WearmapCase& c);

/// Runs `read` (which reads keys of `cfg`); an InputError about a key that a
/// flag set is re-thrown naming the flag and its text instead of "--set".
template <class Read>
auto naming_flags(const WearmapCase& c, Read&& read) -> decltype(read());
InputError name_flag(const WearmapCase& c, const InputError& e);

/// An axis range key: two numbers [MIN, MAX], each in `element`, MIN < MAX;
/// `fallback` when absent. `what` (e.g. "d/l") names the quantity in errors.
std::pair<double, double> read_range(const Config& cfg, const std::string& key, std::pair<double, double> fallback,
                                     const Range& element, const std::string& what);

/// Records a resolved value in the case (so that to_json()/to_toml() hold
/// every parameter the run used, defaults included).
void record(Config& cfg, const std::string& key, const std::string& toml_value);
std::string toml_number(double v);
std::string toml_range(std::pair<double, double> r);

/// The output folder: --out, else [output] dir, else `fallback` (not created here).
std::filesystem::path output_folder(const WearmapCase& c, const Config& cfg, const std::string& fallback);
/// Takes the output folder (created if missing) for this run, before its
/// work: InputError naming --out or output.dir if it cannot be created or
/// written, OutputError if another process writes into it.
OutputLock lock_output_folder(const WearmapCase& c, const std::filesystem::path& out);

template <class Read>
auto naming_flags(const WearmapCase& c, Read&& read) -> decltype(read()) {
  try {
    return read();
  } catch (const InputError& e) {
    throw name_flag(c, e);
  }
}

}  // namespace wearscale::app
