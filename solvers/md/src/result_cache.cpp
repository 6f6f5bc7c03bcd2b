#include "wearscale/md/result_cache.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>

#include <cstdlib>
#include <fstream>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/sha256.hpp"

namespace wearscale::md {

namespace fs = std::filesystem;

std::string cache_key(const std::vector<std::string_view>& parts) {
  Sha256 h;
  h.field("wearscale-md-cache-v1");
  for (auto p : parts) h.field(p);
  return h.hex();
}

ResultCache::ResultCache(fs::path dir) : dir_(std::move(dir)) {}

std::optional<fs::path> ResultCache::find(const std::string& key) const {
  const fs::path e = entry(key);
  std::error_code ec;
  if (fs::is_regular_file(e / complete_marker, ec)) return e;
  return std::nullopt;
}

fs::path ResultCache::begin(const std::string& key) const {
  const fs::path work = dir_ / fmt::format(".{}.partial-{}", key, ::getpid());
  std::error_code ec;
  // Working folders of this key left by processes that no longer exist (killed runs).
  const std::string prefix = fmt::format(".{}.partial-", key);
  for (fs::directory_iterator it(dir_, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const long pid = std::strtol(name.c_str() + prefix.size(), nullptr, 10);
    if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) fs::remove_all(it->path(), ec);
  }
  ec.clear();
  fs::remove_all(work, ec);
  fs::create_directories(work, ec);
  if (ec)
    throw InputError(fmt::format("cannot create the LAMMPS run folder {}: {} (set WEARSCALE_CACHE or md.cache_dir "
                                 "to a writable folder)",
                                 work.string(), ec.message()));
  return work;
}

fs::path ResultCache::commit(const std::string& key, const fs::path& work) const {
  {
    std::ofstream(work / complete_marker) << key << '\n';
  }
  const fs::path e = entry(key);
  std::error_code ec;
  fs::remove_all(e, ec);  // an incomplete or replaced entry of the same key
  fs::rename(work, e, ec);
  if (ec) throw InputError(fmt::format("cannot store the LAMMPS run {} as {}: {}", work.string(), e.string(), ec.message()));
  return e;
}

}  // namespace wearscale::md
