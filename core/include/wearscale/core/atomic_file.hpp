#pragma once
// Files that appear complete or not at all: written under a temporary name in
// the same folder, flushed to disk, then renamed over the final name.
#include <filesystem>
#include <string>
#include <string_view>

namespace wearscale {

/// The temporary name used while `final_path` is being written
/// ("<dir>/.<name>.partial-<pid>"), hidden and unique per process.
std::filesystem::path partial_path(const std::filesystem::path& final_path);

/// fsync()s a finished file and renames it to its final name (POSIX rename
/// is atomic within a file system), then fsyncs the folder.
void commit_file(const std::filesystem::path& partial, const std::filesystem::path& final_path);

/// Writes `content` to `path` atomically (CSV tables, XDMF, JSON).
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

/// Removes the temporary files (and folders) in `dir` left by processes that
/// no longer exist, e.g. a run killed with SIGKILL; returns how many.
std::size_t remove_stale_partials(const std::filesystem::path& dir);

}  // namespace wearscale
