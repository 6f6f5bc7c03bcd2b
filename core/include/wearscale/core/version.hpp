#pragma once
// The version of wearscale and of the libraries it was built with.
#include <string>
#include <utility>
#include <vector>

namespace wearscale {

std::string version();
/// The git revision wearscale was built from ("v0.1.0-12-gabc123def456-dirty"),
/// or "" when it was not built from a git checkout.
std::string git_revision();
/// (library, version) pairs, e.g. ("FFTW", "fftw-3.3.10-sse2-avx").
std::vector<std::pair<std::string, std::string>> library_versions();

}  // namespace wearscale
