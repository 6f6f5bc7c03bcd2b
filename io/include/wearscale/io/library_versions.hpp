#pragma once
// The libraries wearscale was built with and their versions, for
// `wearscale version` and the provenance of outputs.
#include <string>
#include <utility>
#include <vector>

namespace wearscale {

/// (library, version) pairs, e.g. ("FFTW", "fftw-3.3.10-sse2-avx").
std::vector<std::pair<std::string, std::string>> library_versions();

}  // namespace wearscale
