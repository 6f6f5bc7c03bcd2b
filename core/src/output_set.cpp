#include "wearscale/core/output_set.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <map>
#include <mutex>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/text_file.hpp"

namespace wearscale {

namespace fs = std::filesystem;

namespace {

// The open sets, by folder (absolute, normalised): sweeps run several at once.
std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}
std::map<fs::path, OutputSet*>& registry() {
  static std::map<fs::path, OutputSet*> sets;
  return sets;
}

fs::path key_of(const fs::path& dir) {
  std::error_code ec;
  fs::path abs = fs::absolute(dir.empty() ? fs::path(".") : dir, ec);
  return (ec ? dir : abs).lexically_normal() / "";
}

void sync_folder(const fs::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

// A manifest file in `dir`, if it is one (else an empty object: nothing to clean up after).
nlohmann::json previous_manifest(const fs::path& file) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return nlohmann::json::object();
  try {
    auto j = nlohmann::json::parse(read_text_file(file, "summary", std::uintmax_t{1} << 26));
    if (j.is_object()) return j;
  } catch (const std::exception&) {  // not ours, or damaged
  }
  return nlohmann::json::object();
}

nlohmann::json outputs_of(const nlohmann::json& manifest) {
  if (manifest.contains("outputs") && manifest["outputs"].is_object()) return manifest["outputs"];
  return nlohmann::json::object();
}

// A plain file name: the outputs of a set live directly in its folder.
bool plain_name(const std::string& name) {
  return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos;
}

// A subfolder a set may own: one or two plain names, none hidden (never "..", never absolute).
bool owned_folder_name(const fs::path& relative) {
  if (relative.empty() || relative.is_absolute()) return false;
  std::size_t parts = 0;
  for (const auto& part : relative) {
    const std::string name = part.string();
    if (!plain_name(name) || name.front() == '.') return false;
    ++parts;
  }
  return parts <= 2;
}

}  // namespace

void OutputSet::own_folder(const fs::path& relative) {
  if (!owned_folder_name(relative))
    throw std::invalid_argument(fmt::format("OutputSet: '{}' is not a subfolder a set may own", relative.string()));
  if (std::find(folders_.begin(), folders_.end(), relative) == folders_.end()) folders_.push_back(relative);
}

std::vector<fs::path> OutputSet::owned_folders(const nlohmann::json& manifest) {
  std::vector<fs::path> out;
  if (!manifest.is_object() || !manifest.contains("folders") || !manifest["folders"].is_array()) return out;
  for (const auto& f : manifest["folders"])
    if (f.is_string() && owned_folder_name(f.get<std::string>())) out.emplace_back(f.get<std::string>());
  return out;
}

OutputSet::OutputSet(fs::path dir, std::string manifest) : dir_(std::move(dir)), manifest_(std::move(manifest)) {
  create_output_folder(dir_);
  key_ = key_of(dir_);
  std::lock_guard lock(registry_mutex());
  auto& sets = registry();
  if (sets.count(key_) != 0)
    throw std::logic_error(fmt::format("OutputSet: a set is already open for {}", dir_.string()));
  sets[key_] = this;
}

OutputSet::~OutputSet() {
  std::lock_guard lock(registry_mutex());
  registry().erase(key_);
  if (committed_) return;
  for (const auto& [partial, final_path] : files_) {
    std::error_code ec;
    fs::remove(partial, ec);
  }
}

std::vector<fs::path> OutputSet::staged() const {
  std::lock_guard lock(registry_mutex());
  std::vector<fs::path> out;
  for (const auto& f : files_) out.push_back(f.second);
  return out;
}

bool OutputSet::stage(const fs::path& partial, const fs::path& final_path) {
  std::lock_guard lock(registry_mutex());
  const auto it = registry().find(key_of(final_path.parent_path()));
  if (it == registry().end() || it->second->committed_) return false;
  auto& files = it->second->files_;
  for (auto& f : files)
    if (f.second == final_path) {  // written again: the newer version counts
      std::error_code ec;
      if (f.first != partial) fs::remove(f.first, ec);
      f.first = partial;
      return true;
    }
  files.emplace_back(partial, final_path);
  return true;
}

fs::path OutputSet::readable(const fs::path& final_path) {
  std::lock_guard lock(registry_mutex());
  const auto it = registry().find(key_of(final_path.parent_path()));
  if (it != registry().end())
    for (const auto& f : it->second->files_)
      if (f.second == final_path) return f.first;
  return final_path;
}

void OutputSet::commit(nlohmann::json manifest) {
  if (committed_) throw std::logic_error("OutputSet: committed twice");
  const fs::path manifest_file = dir_ / manifest_;
  std::vector<std::pair<fs::path, fs::path>> files;
  {
    std::lock_guard lock(registry_mutex());
    files = files_;
  }
  nlohmann::json outputs = nlohmann::json::object();
  for (const auto& [partial, final_path] : files) {
    std::error_code ec;
    const auto bytes = fs::file_size(partial, ec);
    if (ec) throw OutputError(fmt::format("cannot read {}: {}", partial.string(), ec.message()));
    outputs[final_path.filename().string()] = {{"bytes", bytes}};
  }
  const nlohmann::json previous_summary = previous_manifest(manifest_file);
  const nlohmann::json previous = outputs_of(previous_summary);
  const std::vector<fs::path> previous_folders = owned_folders(previous_summary);

  // 1. No manifest while the folder changes: it never vouches for a mix.
  std::error_code ec;
  fs::remove(manifest_file, ec);
  if (ec) throw OutputError(fmt::format("cannot replace {}: {}", manifest_file.string(), ec.message()));
  sync_folder(dir_);
  // 2. The new outputs under their final names.
  for (const auto& [partial, final_path] : files)
    if (::rename(partial.c_str(), final_path.c_str()) != 0)
      throw OutputError(fmt::format("cannot rename to {}: {}", final_path.string(), std::strerror(errno)));
  {
    std::lock_guard lock(registry_mutex());
    committed_ = true;  // the staged names are gone: nothing left to remove
    registry().erase(key_);
  }
  // 3. Outputs of the previous run that this one did not replace.
  for (const auto& [name, info] : previous.items()) {
    (void)info;
    if (!plain_name(name) || outputs.contains(name) || name == manifest_) continue;
    fs::remove(dir_ / name, ec);
  }
  // ... and the subfolders it owned (a sweep's runs) that this one does not own again, then the series
  // folders they leave empty.
  for (const auto& folder : previous_folders) {
    if (std::find(folders_.begin(), folders_.end(), folder) != folders_.end()) continue;
    bool holds_one = false;  // a folder of this set inside it (a series folder kept)
    for (const auto& mine : folders_) holds_one = holds_one || *mine.begin() == folder;
    if (holds_one) continue;
    fs::remove_all(dir_ / folder, ec);
    if (const fs::path parent = folder.parent_path(); !parent.empty()) fs::remove(dir_ / parent, ec);  // if empty
  }
  sync_folder(dir_);
  // 4. The manifest, last.
  manifest["outputs"] = outputs;
  if (!folders_.empty()) {
    manifest["folders"] = nlohmann::json::array();
    for (const auto& f : folders_) manifest["folders"].push_back(f.generic_string());
  }
  write_file_atomically(manifest_file, manifest.dump(2) + "\n", Commit::Now);
}

std::string OutputSet::verify(const fs::path& dir, const nlohmann::json& manifest) {
  if (!manifest.is_object() || !manifest.contains("outputs") || !manifest["outputs"].is_object())
    return "it lists no outputs (written by an older wearscale?)";
  for (const auto& [name, info] : manifest["outputs"].items()) {
    if (!plain_name(name)) return fmt::format("'{}' is not a file name", name);
    std::error_code ec;
    const auto bytes = fs::file_size(dir / name, ec);
    if (ec) return fmt::format("{}: missing", name);
    const auto expected = info.is_object() && info.contains("bytes") && info["bytes"].is_number_unsigned()
                              ? info["bytes"].get<std::uintmax_t>()
                              : std::uintmax_t(-1);
    if (bytes != expected) return fmt::format("{}: {} bytes, the summary says {}", name, bytes, info.dump());
  }
  return {};
}

}  // namespace wearscale
