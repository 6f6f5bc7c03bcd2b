#pragma once
// The version of wearscale (that of the libraries it was built with:
// io/library_versions.hpp).
#include <string>

namespace wearscale {

std::string version();
/// The git revision wearscale was built from ("v0.1.0-12-gabc123def456-dirty"),
/// or "" when it was not built from a git checkout.
std::string git_revision();

}  // namespace wearscale
