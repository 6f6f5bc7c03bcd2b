#pragma once
// Where an external program (gnuplot, lmp, mpirun) is: searched on PATH as a
// shell would, without starting a shell.
#include <filesystem>
#include <string>

namespace wearscale {

/// An executable regular file of that name in a directory of PATH (the first),
/// or an empty path.
std::filesystem::path find_on_path(const std::string& name);

}  // namespace wearscale
