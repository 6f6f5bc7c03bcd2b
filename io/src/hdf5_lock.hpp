#pragma once
// The HDF5 lock, shared by the reader and writer wrappers (hdf5_file.cpp) and
// the child processes that try a read first (H5Reader::guarded).
#include <mutex>

namespace wearscale::detail {

/// Serialises every call into HDF5 (Debian's serial build is not thread-safe).
std::recursive_mutex& hdf5_mutex();

}  // namespace wearscale::detail
