#include "wearscale/core/output_lock.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/utc_time.hpp"

namespace wearscale {

namespace fs = std::filesystem;

namespace {

std::string host_name() {
  char buf[256] = {};
  if (::gethostname(buf, sizeof buf - 1) != 0) return "?";
  return buf;
}

// The holder a lock file describes: "pid: 123\nhost: h\nstarted: …\ncommand: …\n".
struct Holder {
  long pid = 0;
  std::string host, started, command, ensemble;
};

Holder read_holder(int fd) {
  char buf[4096] = {};
  const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
  Holder h;
  if (n <= 0) return h;
  std::string_view text(buf, static_cast<std::size_t>(n));
  while (!text.empty()) {
    const auto end = std::min(text.find('\n'), text.size());
    const std::string_view line = text.substr(0, end);
    text.remove_prefix(std::min(end + 1, text.size()));
    const auto colon = line.find(": ");
    if (colon == std::string_view::npos) continue;
    const std::string_view key = line.substr(0, colon), value = line.substr(colon + 2);
    if (key == "pid") h.pid = std::atol(std::string(value).c_str());
    if (key == "host") h.host = value;
    if (key == "started") h.started = value;
    if (key == "command") h.command = value;
    if (key == "ensemble") h.ensemble = value;
  }
  return h;
}

std::string describe(const Holder& h) {
  if (h.pid <= 0) return "another process";
  std::string s = fmt::format("process {}", h.pid);
  if (!h.host.empty() && h.host != host_name()) s += fmt::format(" on {}", h.host);
  if (!h.command.empty()) s += fmt::format(" ({})", h.command);
  if (!h.started.empty()) s += fmt::format(", started {}", h.started);
  return s;
}

bool alive_here(const Holder& h) {
  return h.pid > 0 && h.pid != ::getpid() && h.host == host_name() &&
         (::kill(static_cast<pid_t>(h.pid), 0) == 0 || errno == EPERM);
}

bool same_file(int fd, const fs::path& path) {
  struct stat a {}, b {};
  return ::fstat(fd, &a) == 0 && ::stat(path.c_str(), &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

[[noreturn]] void refuse(const fs::path& what, const Holder& holder) {
  throw OutputError(fmt::format("{} is being written by {}; wait for it to finish, or give another output folder",
                                what.string(), describe(holder)));
}

[[noreturn]] void refuse_other_ensemble(const fs::path& what, const Holder& holder) {
  throw OutputError(fmt::format("{} is being written by the shards of another ensemble ({}); a shard (--task K/N) "
                                "shares a folder only with the shards of the same case, sweep and options; give "
                                "another output folder",
                                what.string(), describe(holder)));
}

}  // namespace

OutputLock OutputLock::folder(const fs::path& dir, const std::string& command, Mode mode, const std::string& ensemble) {
  fs::path top;  // the outermost folder that does not exist yet
  std::error_code ec;
  for (fs::path p = dir; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    top = p;
    if (p == p.parent_path()) break;
  }
  create_output_folder(dir);
  OutputLock lock(dir / kFolderLockName, dir, command, mode, ensemble);
  if (!top.empty()) lock.created_ = dir, lock.created_top_ = top;
  return lock;
}

OutputLock OutputLock::file(const fs::path& path, const std::string& command) {
  if (!path.parent_path().empty()) create_output_folder(path.parent_path());
  return OutputLock(path.parent_path() / ("." + path.filename().string() + ".lock"), path, command, Mode::Exclusive, {});
}

OutputLock::OutputLock(fs::path lock_file, fs::path what, const std::string& command, Mode mode,
                       const std::string& ensemble)
    : file_(std::move(lock_file)), shared_(mode == Mode::Shared) {
  if (shared_ && (ensemble.empty() || ensemble.find('\n') != std::string::npos))
    throw std::invalid_argument("OutputLock: a shared lock needs an ensemble id of one line");
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
      throw OutputError(fmt::format("{}: cannot write into it: {}", what.string(), std::strerror(errno)));
    int locked = ::flock(fd, (shared_ ? LOCK_SH : LOCK_EX) | LOCK_NB);
    // A shard that starts as another one writes its id (a moment's exclusive lock): try again briefly.
    for (int wait = 0; shared_ && locked != 0 && errno == EWOULDBLOCK && wait < 50; ++wait) {
      ::usleep(2000);
      locked = ::flock(fd, LOCK_SH | LOCK_NB);
    }
    if (locked != 0) {
      const int error = errno;
      const Holder holder = read_holder(fd);
      if (error == EWOULDBLOCK) {
        ::close(fd);
        refuse(what, holder);
      }
      if (error != ENOLCK && error != EINVAL && error != ENOSYS && error != EOPNOTSUPP) {
        ::close(fd);
        throw OutputError(fmt::format("{}: cannot lock it: {}", what.string(), std::strerror(error)));
      }
      // No flock on this file system: the pid written there is the lock.
      if (alive_here(holder) && !(shared_ && holder.ensemble == ensemble)) {
        ::close(fd);
        refuse(what, holder);
      }
      log::debug("{}: the file system does not support flock; locked by pid only", what.string());
    } else if (!same_file(fd, file_)) {
      ::close(fd);  // the previous holder removed it between our open and flock: take the new one
      continue;
    }
    std::string content = fmt::format("pid: {}\nhost: {}\nstarted: {}\ncommand: {}\n", ::getpid(), host_name(),
                                      utc_now(), command);
    if (shared_) content += fmt::format("ensemble: {}\n", ensemble);
    const auto write_content = [&] {
      try {
        if (::ftruncate(fd, 0) != 0)
          throw OutputError(fmt::format("cannot write {}: {}", file_.string(), std::strerror(errno)));
        write_all(fd, content.data(), content.size(), file_);
      } catch (const OutputError& e) {
        ::unlink(file_.c_str());
        ::close(fd);
        throw OutputError(fmt::format("{}: cannot write into it ({})", what.string(), e.what()));
      }
    };
    if (shared_ && ::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      // Other shards hold it: the file names their ensemble. Shards that
      // started together may find it without one (or a killed run's): each
      // writes its own, and reads back which one stands.
      Holder holder = read_holder(fd);
      if (holder.ensemble.empty()) {
        write_content();
        holder = read_holder(fd);
      }
      if (holder.ensemble != ensemble) {
        ::close(fd);
        refuse_other_ensemble(what, holder);
      }
      fd_ = fd;
      return;
    }
    // Alone on it (exclusive, or the first shard): say who holds it, then (a
    // shard) let the other shards of the ensemble in.
    write_content();
    if (shared_) ::flock(fd, LOCK_SH | LOCK_NB);  // a conversion: never refused to the holder alone
    fd_ = fd;
    return;
  }
  throw OutputError(fmt::format("{}: cannot lock it: the lock file keeps changing", what.string()));
}

OutputLock::OutputLock(OutputLock&& other) noexcept
    : file_(std::move(other.file_)), created_(std::move(other.created_)), created_top_(std::move(other.created_top_)),
      fd_(other.fd_), shared_(other.shared_) {
  other.fd_ = -1;
}

OutputLock& OutputLock::operator=(OutputLock&& other) noexcept {
  if (this != &other) {
    release();
    file_ = std::move(other.file_);
    created_ = std::move(other.created_);
    created_top_ = std::move(other.created_top_);
    fd_ = other.fd_;
    shared_ = other.shared_;
    other.fd_ = -1;
  }
  return *this;
}

OutputLock::~OutputLock() { release(); }

void OutputLock::release() noexcept {
  if (fd_ < 0) return;
  // A shard leaves the file to the other shards still holding it.
  if (shared_ && ::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    fd_ = -1;
    return;
  }
  ::unlink(file_.c_str());  // while still holding it: a process waiting on the old file retries on a new one
  ::close(fd_);
  fd_ = -1;
  // Folders this lock created and nothing was written into: gone again (rmdir refuses non-empty ones).
  if (created_.empty()) return;
  for (fs::path p = created_;; p = p.parent_path()) {
    if (::rmdir(p.c_str()) != 0 || p == created_top_ || p.empty() || p == p.parent_path()) break;
  }
}

}  // namespace wearscale
