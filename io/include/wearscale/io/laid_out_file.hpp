#pragma once
// An HDF5 file whose large fields are written in place by the processes that
// hold their rows (the ranks of a slab run above its gather limit), so that no
// process ever holds a whole field.
//
// HDF5 lays the file out on disk (H5Storage::Disk): the small datasets and
// attributes, and each field contiguous, reserved and unfilled. It does so in
// a child process: HDF5 1.10 can crash when a write of its own fails (a full
// disk, an I/O error), and such a crash, or any failure there, becomes an
// OutputError here with the temporary file removed. The parent then writes
// the values at the reserved offsets (write_in_place on partial()) and
// commits: the file reaches its final name complete (with its OutputSet) or
// not at all.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <vector>

#include "wearscale/core/atomic_file.hpp"

namespace wearscale {

class H5Writer;

class LaidOutFile {
 public:
  /// `lay_out(h5)` writes the file's small contents and reserves its fields
  /// (H5Writer::reserve_field), returning their offsets in the order it
  /// reserved them; it runs in a child process. OutputError naming
  /// `final_path` if the child fails or crashes.
  LaidOutFile(std::filesystem::path final_path, const std::function<std::vector<std::uint64_t>(H5Writer&)>& lay_out,
              Commit mode = Commit::WithItsSet);
  /// Removes the temporary file unless committed.
  ~LaidOutFile();
  LaidOutFile(const LaidOutFile&) = delete;
  LaidOutFile& operator=(const LaidOutFile&) = delete;

  const std::filesystem::path& partial() const { return partial_; }
  const std::filesystem::path& final_path() const { return final_; }
  /// The reserved fields' byte offsets, as `lay_out` returned them.
  const std::vector<std::uint64_t>& offsets() const { return offsets_; }
  /// The file, its fields written, to its final name (fsynced first).
  void commit();

 private:
  std::filesystem::path final_, partial_;
  Commit mode_;
  std::vector<std::uint64_t> offsets_;
  bool committed_ = false;
};

}  // namespace wearscale
