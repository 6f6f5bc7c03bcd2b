#pragma once
// The version of wearscale and of the libraries it was built with.
#include <string>
#include <utility>
#include <vector>

namespace wearscale {

std::string version();
/// (library, version) pairs, e.g. ("FFTW", "fftw-3.3.10-sse2-avx").
std::vector<std::pair<std::string, std::string>> library_versions();

}  // namespace wearscale
