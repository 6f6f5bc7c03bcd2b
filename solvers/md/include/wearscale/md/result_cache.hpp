#pragma once
// A cache of finished LAMMPS runs: one folder per run, named by the SHA-256
// of every input of that run (the spec's fingerprint, the deck text, the
// LAMMPS version, the potential file contents, and for a shear test of SiO2
// the key of the quench it starts from). Re-running identical inputs reads
// the folder instead of calling lmp. A run happens in a hidden partial
// folder that is renamed to its key when it succeeded, so a failed or killed
// run never leaves an entry.
//
// One writer per entry: whoever looks an entry up to run it when missing
// holds the entry's lock (lock(): flock on <dir>/.<key>.lock) from the look-up
// to the commit, so of several processes (the ranks of an MPI job, a job
// array's tasks, two users of one cache) asking for the same run at once one
// runs it and the others wait, then read its entry; none runs it twice, none
// sees a half-written entry (the rename is atomic).
//
// Location: cache_folder("lammps") (core/cache_folder.hpp:
// $WEARSCALE_CACHE/lammps, else ~/.cache/wearscale/lammps).
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace wearscale::md {


/// SHA-256 of the parts, each length-prefixed: the cache key.
std::string cache_key(const std::vector<std::string_view>& parts);

/// An exclusive hold on one entry of a cache, released when it goes out of scope.
class EntryLock {
 public:
  EntryLock() = default;
  EntryLock(int fd, std::string path) : fd_(fd), path_(std::move(path)) {}
  EntryLock(EntryLock&& o) noexcept : fd_(o.fd_), path_(std::move(o.path_)) { o.fd_ = -1; }
  EntryLock& operator=(EntryLock&& o) noexcept;
  EntryLock(const EntryLock&) = delete;
  EntryLock& operator=(const EntryLock&) = delete;
  ~EntryLock();
  bool held() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
  std::string path_;
};

class ResultCache {
 public:
  explicit ResultCache(std::filesystem::path dir);
  const std::filesystem::path& dir() const { return dir_; }

  /// Waits until no other process or thread holds `key`'s entry and holds it
  /// (see above); `on_wait` is called once if it has to wait (a message).
  /// InputError if the lock file cannot be created (a read-only cache).
  EntryLock lock(const std::string& key, const std::function<void()>& on_wait = {}) const;

  /// The entry of `key` if it exists and is complete.
  std::optional<std::filesystem::path> find(const std::string& key) const;
  /// A fresh, empty working folder for `key` (hidden, unique to this process).
  std::filesystem::path begin(const std::string& key) const;
  /// Marks the working folder complete and renames it to the entry of `key`
  /// (replacing an older entry of the same key); returns the entry.
  std::filesystem::path commit(const std::string& key, const std::filesystem::path& work) const;
  /// The folder an entry of `key` has (whether or not it exists).
  std::filesystem::path entry(const std::string& key) const { return dir_ / key; }

  /// Name of the marker file a complete entry holds.
  static constexpr const char* complete_marker = "COMPLETE";

 private:
  std::filesystem::path dir_;
};

}  // namespace wearscale::md
