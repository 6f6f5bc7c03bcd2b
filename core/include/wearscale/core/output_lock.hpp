#pragma once
// One writer per output folder. A run holds an exclusive lock on its output
// folder (`<dir>/.wearscale.lock`, flock(2)) from before it reads a
// checkpoint until it has written its last file; a second process asking for
// the same folder is refused with an OutputError (exit 2) naming the
// holder's pid and command. The kernel releases the lock when the holder
// exits or is killed, so a lock is never stale; a killed holder leaves only
// the small lock file, which the next run reuses.
//
// A single output file (`surface generate --out a.h5`) is locked the same way
// by `.<name>.lock` beside it, so two generations into one folder proceed.
//
// Shards of one ensemble (`--task K/N`) share a folder: each takes the
// folder's lock in the Shared mode with the ensemble's id (flock LOCK_SH, the
// id written in the lock file) and writes only into its own runs' subfolders,
// each under its own exclusive lock. A shard of another ensemble (another id)
// and an exclusive holder (a whole run, `wearscale merge`) are refused, and a
// shard is refused while an exclusive holder runs.
//
// On a file system without flock (some cluster file systems) the lock falls
// back to the pid in the lock file: a live process on this host named there
// still refuses a second writer.
#include <filesystem>
#include <string>

namespace wearscale {

class OutputLock {
 public:
  enum class Mode { Exclusive, Shared };

  /// Locks the folder `dir` (created if missing) for `command` (a line for
  /// the refusal message, e.g. "wearscale run cases/a.toml"). A folder it
  /// created and that is still empty when the lock is released (the run
  /// failed before writing anything) is removed again.
  /// Shared: `ensemble` (an id, no newline) names the ensemble whose shards may share it.
  static OutputLock folder(const std::filesystem::path& dir, const std::string& command,
                           Mode mode = Mode::Exclusive, const std::string& ensemble = {});
  /// Locks one output file (its folder must exist or is created).
  static OutputLock file(const std::filesystem::path& path, const std::string& command);

  OutputLock(OutputLock&& other) noexcept;
  OutputLock& operator=(OutputLock&& other) noexcept;
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;
  /// Releases the lock and removes the lock file.
  ~OutputLock();

  const std::filesystem::path& lock_file() const { return file_; }

  /// The lock file of folder `dir` (".wearscale.lock"): not an output.
  static constexpr const char* kFolderLockName = ".wearscale.lock";

 private:
  OutputLock(std::filesystem::path lock_file, std::filesystem::path what, const std::string& command, Mode mode,
             const std::string& ensemble);
  void release() noexcept;
  std::filesystem::path file_;
  std::filesystem::path created_, created_top_;  // the folder it created, and the outermost parent it created
  int fd_ = -1;
  bool shared_ = false;
};

}  // namespace wearscale
