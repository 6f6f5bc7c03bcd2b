#pragma once
// A cache of finished LAMMPS runs: one folder per run, named by the SHA-256
// of every input of that run (the spec's fingerprint, the deck text, the
// LAMMPS version, the potential file contents, and for a shear test of SiO2
// the key of the quench it starts from). Re-running identical inputs reads
// the folder instead of calling lmp. A run happens in a hidden partial
// folder that is renamed to its key when it succeeded, so a failed or killed
// run never leaves an entry.
//
// Location: cache_folder("lammps") (core/cache_folder.hpp:
// $WEARSCALE_CACHE/lammps, else ~/.cache/wearscale/lammps).
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace wearscale::md {


/// SHA-256 of the parts, each length-prefixed: the cache key.
std::string cache_key(const std::vector<std::string_view>& parts);

class ResultCache {
 public:
  explicit ResultCache(std::filesystem::path dir);
  const std::filesystem::path& dir() const { return dir_; }

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
