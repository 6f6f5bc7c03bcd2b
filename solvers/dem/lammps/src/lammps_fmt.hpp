#pragma once
// Debian 12's LAMMPS headers (29 Sep 2021) call fmt::make_args_checked, which
// fmt 9 (Debian's libfmt-dev) no longer has: LAMMPS itself was built with
// its own copy of fmt, whose headers liblammps-dev does not ship. The same
// function on fmt 9's terms, declared before any LAMMPS header (CMake
// includes this file first in every source of this library); it only builds
// the argument store of a message LAMMPS formats.
#include <fmt/format.h>

#if FMT_VERSION >= 90000
namespace fmt {
template <typename... Args, typename S>
auto make_args_checked(const S&, Args&&... args) {
  return fmt::make_format_args(args...);
}
}  // namespace fmt
#endif
