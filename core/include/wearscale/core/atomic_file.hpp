#pragma once
// Files that appear complete or not at all: written under a temporary name in
// the same folder, every write checked, flushed to disk, then renamed over the
// final name. A full disk, a read-only folder or a vanished folder gives an
// OutputError naming the file (exit 2), and the temporary file is removed, so
// nothing partial ever carries a final name.
//
// The outputs of one run go further: they reach their final names together,
// when the run's OutputSet commits (output_set.hpp).
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace wearscale {

/// The temporary name used while `final_path` is being written
/// ("<dir>/.<name>.partial-<pid>"), hidden and unique per process.
std::filesystem::path partial_path(const std::filesystem::path& final_path);

/// How a finished file reaches its final name.
enum class Commit {
  WithItsSet,  ///< with the OutputSet open for its folder, if any (the outputs of a run)
  Now,         ///< at once, whatever set is open (checkpoints, caches)
};

/// fsync()s a finished temporary file and renames it to its final name (POSIX
/// rename is atomic within a file system), then fsyncs the folder. With
/// Commit::WithItsSet and an OutputSet open for the folder, the file is only
/// staged: it reaches its final name when the set commits. OutputError if the
/// file system refuses (the temporary file then removed).
void commit_file(const std::filesystem::path& partial, const std::filesystem::path& final_path,
                 Commit mode = Commit::WithItsSet);

/// Writes `content` to `path` atomically (CSV tables, XDMF, JSON).
void write_file_atomically(const std::filesystem::path& path, std::string_view content,
                           Commit mode = Commit::WithItsSet);

/// Writes `content` to `path` directly, every write checked: for temporary
/// files that never get a final name (a gnuplot script).
void write_temporary_file(const std::filesystem::path& path, std::string_view content);

/// Writes all of `size` bytes to the open file `fd` (retrying short writes
/// and EINTR); OutputError naming `name` if the disk refuses.
void write_all(int fd, const void* data, std::size_t size, const std::filesystem::path& name);

/// Reserves the first `size` bytes of the existing file `path` on disk
/// (posix_fallocate: a sparse region gets its blocks now), so that writes into
/// them cannot meet a full disk later; OutputError naming it if they do not fit.
void reserve_space(const std::filesystem::path& path, std::uint64_t size);

/// Writes `size` bytes at byte `offset` of the existing file `path` (a region
/// another process laid out, e.g. one rank's rows of a field) and flushes them
/// to disk, every write checked; OutputError naming it.
void write_in_place(const std::filesystem::path& path, std::uint64_t offset, const void* data, std::size_t size);

/// Creates the folder `dir` and its parents; OutputError naming it if that
/// fails (a file in the way, a read-only file system, no permission).
void create_output_folder(const std::filesystem::path& dir);

/// Removes the temporary files (and folders) in `dir` left by processes that
/// no longer exist, e.g. a run killed with SIGKILL; returns how many.
std::size_t remove_stale_partials(const std::filesystem::path& dir);

}  // namespace wearscale
