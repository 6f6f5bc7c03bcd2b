#include "wearscale/md/result_cache.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>

#include <cstdlib>
#include <cstring>
#include <condition_variable>
#include <fstream>
#include <mutex>
#include <set>

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

namespace {
// flock excludes processes (and, on a local file system, each open() of one
// process); on NFS it is emulated by POSIX locks, which do not exclude the
// threads of one process: those wait on this set of held lock files first.
std::mutex g_held_mutex;
std::condition_variable g_held_changed;
std::set<std::string> g_held;
}  // namespace

EntryLock& EntryLock::operator=(EntryLock&& o) noexcept {
  if (this != &o) {
    this->~EntryLock();
    fd_ = o.fd_;
    path_ = std::move(o.path_);
    o.fd_ = -1;
  }
  return *this;
}

EntryLock::~EntryLock() {
  if (fd_ < 0) return;
  ::flock(fd_, LOCK_UN);
  ::close(fd_);  // the lock file stays: removing it would race with a process about to lock it
  fd_ = -1;
  {
    std::lock_guard guard(g_held_mutex);
    g_held.erase(path_);
  }
  g_held_changed.notify_all();
}

ResultCache::ResultCache(fs::path dir) : dir_(std::move(dir)) {}

EntryLock ResultCache::lock(const std::string& key, const std::function<void()>& on_wait) const {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  const std::string path = (dir_ / fmt::format(".{}.lock", key)).string();
  bool told = false;
  {
    std::unique_lock guard(g_held_mutex);
    if (g_held.count(path) != 0 && on_wait) {
      told = true;
      on_wait();
    }
    g_held_changed.wait(guard, [&] { return g_held.count(path) == 0; });
    g_held.insert(path);
  }
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) {
    const int err = errno;
    {
      std::lock_guard guard(g_held_mutex);
      g_held.erase(path);
    }
    g_held_changed.notify_all();
    throw InputError(fmt::format("cannot create the LAMMPS cache lock {}: {} (set WEARSCALE_CACHE or md.cache_dir "
                                 "to a writable folder)",
                                 path, std::strerror(err)));
  }
  EntryLock held(fd, path);
  if (::flock(fd, LOCK_EX | LOCK_NB) == 0) return held;
  if (errno == EWOULDBLOCK && !told && on_wait) on_wait();
  while (::flock(fd, LOCK_EX) != 0) {
    if (errno == EINTR) continue;
    throw InputError(fmt::format("cannot lock the LAMMPS cache entry {}: {} (a cache on a file system without "
                                 "locks; set WEARSCALE_CACHE or md.cache_dir to a local or NFSv4 folder)",
                                 path, std::strerror(errno)));
  }
  return held;
}

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
