#pragma once
// A junction run of nano/dem on the wire between the ranks of an mpirun job:
// its spec out to the rank that runs it, its result back, as CBOR (every
// double as its 8 bytes, so a farmed run is the serial one bit for bit).
#include <string>

#include "wearscale/dem/junction_strength.hpp"

namespace wearscale::coupling {

std::string to_message(const dem::JunctionStrengthSpec& spec);
dem::JunctionStrengthSpec spec_from_message(const std::string& message);

std::string to_message(const dem::JunctionStrengthResult& result);
dem::JunctionStrengthResult result_from_message(const std::string& message);

}  // namespace wearscale::coupling
