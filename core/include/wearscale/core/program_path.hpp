#pragma once
// Where an external program (gnuplot, lmp, mpirun) is: searched on PATH as a
// shell would, without starting a shell.
#include <filesystem>
#include <string>

namespace wearscale {

/// Whether `file` is a regular file this process may execute.
bool is_executable_file(const std::filesystem::path& file);

/// An executable regular file of that name in a directory of PATH (the first),
/// or an empty path.
std::filesystem::path find_on_path(const std::string& name);

}  // namespace wearscale
