#pragma once
// The physical bounds of a run's headline figures, checked alike wherever a
// result comes from: computed by this run (a figure outside them is a
// numerical failure, exit 1), read back from the summary.json of a completed
// run on --resume, or from a shard's run by `wearscale merge` (a figure
// outside them is a summary no run writes: refused, exit 2). A checksum would
// only prove the bytes unchanged; this proves them a possible result.
#include <string>

#include <nlohmann/json.hpp>

namespace wearscale::studies {

/// "" if `value` (in `unit`) is within the physical bounds of the figure
/// `name`, else why not ("pin_wear = -1 m^3: a worn volume is ≥ 0").
std::string result_outside_bounds(const std::string& name, double value, const std::string& unit);

/// "" if `results` is a table of headline figures ({name: {value, unit,
/// description}}) each within its bounds, else the first problem found.
std::string results_problem(const nlohmann::json& results);

}  // namespace wearscale::studies
