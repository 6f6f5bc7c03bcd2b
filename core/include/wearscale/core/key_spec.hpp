#pragma once
// One key of a case as `--help`, "did you mean", completion and docs/keys.md
// show it: its full dotted name, type, allowed values, unit, default and
// meaning. Key tables (io/key_table.hpp) produce these rows; so may a study
// for a key it reads by hand. In core because a scale backend's registry entry
// (core/registry.hpp) holds the rows of its keys.
#include <string>
#include <vector>

namespace wearscale {

struct KeySpec {
  std::string key;       ///< full case key, "contact.mean_pressure"
  std::string type;      ///< "number", "integer", "string", "choice", "path", "table", "boolean", "list",
                         ///< "range" ([MIN, MAX]; its alias flag takes MIN:MAX)
  std::string range;     ///< allowed values in words: "≥ 0", "(0, 0.5]", "none | coulomb | tresca"
  std::string unit;      ///< SI unit of a quantity ("Pa"), "1" for a number without one, "" otherwise
  std::string fallback;  ///< default value as text, "" when the key is required or optional
  std::string doc;       ///< one line
  std::string flag;      ///< the command-line alias of the key's command, "--pressure", or ""
  std::string switch_value = {};  ///< a flag without a value sets the key to this ("--no-strengths": "false")
  /// A "list" key whose alias flag takes plain numbers in this unit separated by commas
  /// ("--pressures 0,10" with "GPa": ["0 GPa", "10 GPa"]); "" for a flag that takes the key's value as it is.
  std::string list_unit = {};
};

using Schema = std::vector<KeySpec>;

}  // namespace wearscale
