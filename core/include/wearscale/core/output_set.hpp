#pragma once
// The outputs of one run, published together. While an OutputSet is open for
// a folder, the files a run finishes there (H5Writer::commit,
// write_file_atomically, write_csv, a plot) stay under their temporary names;
// commit() then
//   1. removes the folder's previous manifest (its summary),
//   2. renames every staged file to its final name,
//   3. removes the outputs the previous manifest listed that this run did not
//      write again,
//   4. writes the new manifest last, listing every output with its size.
// So a folder with a manifest holds exactly the outputs it lists, all of one
// run; a run killed (or failing) before step 4 leaves no manifest, never a
// mix presented as a result. Without commit() (an error, SIGINT) the staged
// files are removed.
//
// Files in subfolders of `dir` are not part of the set, except the folders a
// set owns (own_folder: the runs of a sweep), which the manifest lists under
// "folders" and which step 3 removes in turn when the next run of the folder
// does not own them again. Checkpoints are committed with Commit::Now,
// outside any set. That is the one rule for what a run may remove: only what
// the previous manifest of the same folder lists (what that run wrote).
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace wearscale {

class OutputSet {
 public:
  /// Opens the set of `dir` (created if missing); `manifest` is the name of
  /// the file commit() writes last ("summary.json").
  OutputSet(std::filesystem::path dir, std::string manifest);
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  /// Publishes the set (steps 1-4 above); `manifest` gets an "outputs" object
  /// {file name: {"bytes": size}}, the manifest itself excluded.
  void commit(nlohmann::json manifest);

  const std::filesystem::path& dir() const { return dir_; }
  /// Makes the subfolder `relative` (one or two plain names: "thickness=1e-06", or
  /// "hurst=0.6/thickness=1e-06" in a series) part of the set: listed in the
  /// manifest under "folders", kept by commit; std::invalid_argument for
  /// another kind of path.
  void own_folder(const std::filesystem::path& relative);

  /// The subfolders the manifest `manifest` (a summary.json) says its run
  /// owned: the folders a next run of that folder may remove.
  static std::vector<std::filesystem::path> owned_folders(const nlohmann::json& manifest);

  /// Final paths of the files staged so far.
  std::vector<std::filesystem::path> staged() const;

  /// Where `final_path` can be read now: its temporary file while an open set
  /// holds it, else `final_path` itself.
  static std::filesystem::path readable(const std::filesystem::path& final_path);
  /// commit_file's hook: true if an open set of `final_path`'s folder took
  /// the finished temporary file `partial` (replacing an earlier version).
  static bool stage(const std::filesystem::path& partial, const std::filesystem::path& final_path);

  /// "" if every output a manifest lists is in `dir` with its recorded size,
  /// else what is missing or differs ("run.h5: 0 bytes, the manifest says 61112").
  static std::string verify(const std::filesystem::path& dir, const nlohmann::json& manifest);

 private:
  std::filesystem::path dir_, key_;
  std::string manifest_;
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>> files_;  // partial, final
  std::vector<std::filesystem::path> folders_;  // owned subfolders, relative
  bool committed_ = false;
};

}  // namespace wearscale
