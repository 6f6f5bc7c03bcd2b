#include "wearscale/core/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/output_set.hpp"

namespace wearscale {

namespace {

[[noreturn]] void io_error(const std::string& what, const std::filesystem::path& p, int error) {
  // EFBIG: the file size limit of the process (ulimit -f); SIGXFSZ is ignored so that it arrives here.
  throw OutputError(fmt::format("{} {}: {}{}", what, p.string(), std::strerror(error),
                                error == EFBIG ? " (beyond this process' file size limit, ulimit -f)" : ""));
}

// fsync of a file or folder. EINVAL/EROFS: a file system without fsync (some
// FUSE and pseudo file systems), where rename is still atomic. A write error
// reported late (EIO, ENOSPC, EDQUOT) is an error of that file.
void fsync_path(const std::filesystem::path& p, int flags, bool must_succeed) {
  const int fd = ::open(p.c_str(), flags | O_CLOEXEC);
  if (fd < 0) {
    if (must_succeed) io_error("cannot open", p, errno);
    return;  // a folder we cannot open (odd file systems): rename is still atomic
  }
  const int status = ::fsync(fd);
  const int error = errno;
  ::close(fd);
  if (status != 0 && must_succeed && error != EINVAL && error != EROFS) io_error("cannot write", p, error);
}

void remove_quietly(const std::filesystem::path& p) {
  std::error_code ec;
  std::filesystem::remove(p, ec);
}

}  // namespace

std::filesystem::path partial_path(const std::filesystem::path& final_path) {
  const auto name = fmt::format(".{}.partial-{}", final_path.filename().string(), ::getpid());
  return final_path.parent_path() / name;
}

void write_all(int fd, const void* data, std::size_t size, const std::filesystem::path& name) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      io_error("cannot write", name, errno);
    }
    if (n == 0) io_error("cannot write", name, ENOSPC);
    p += n;
    size -= static_cast<std::size_t>(n);
  }
}

void reserve_space(const std::filesystem::path& path, std::uint64_t size) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) io_error("cannot write", path, errno);
  int error = 0;
  do {
    error = ::posix_fallocate(fd, 0, static_cast<off_t>(size));  // returns the error, does not set errno
  } while (error == EINTR);
  ::close(fd);
  if (error != 0) io_error("cannot reserve space for", path, error);
}

void write_in_place(const std::filesystem::path& path, std::uint64_t offset, const void* data, std::size_t size) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) io_error("cannot write", path, errno);
  const char* p = static_cast<const char*>(data);
  auto at = static_cast<off_t>(offset);
  try {
    while (size > 0) {
      const ssize_t n = ::pwrite(fd, p, size, at);
      if (n < 0) {
        if (errno == EINTR) continue;
        io_error("cannot write", path, errno);
      }
      if (n == 0) io_error("cannot write", path, ENOSPC);
      p += n;
      at += n;
      size -= static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0 && errno != EINVAL) io_error("cannot write", path, errno);  // EINVAL: a file system without fsync
  } catch (...) {
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0) io_error("cannot write", path, errno);
}

void commit_file(const std::filesystem::path& partial, const std::filesystem::path& final_path, Commit mode) {
  try {
    fsync_path(partial, O_RDONLY, true);
    if (mode == Commit::WithItsSet && OutputSet::stage(partial, final_path)) return;
    if (::rename(partial.c_str(), final_path.c_str()) != 0) io_error("cannot rename to", final_path, errno);
  } catch (const OutputError&) {
    remove_quietly(partial);  // a file that cannot be committed is never left behind (e.g. a plot's image)
    throw;
  }
  const auto dir = final_path.parent_path().empty() ? std::filesystem::path(".") : final_path.parent_path();
  fsync_path(dir, O_RDONLY | O_DIRECTORY, false);
}

void write_temporary_file(const std::filesystem::path& path, std::string_view content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) io_error("cannot write", path, errno);
  try {
    write_all(fd, content.data(), content.size(), path);
  } catch (...) {
    ::close(fd);
    remove_quietly(path);
    throw;
  }
  if (::close(fd) != 0) {
    const int error = errno;
    remove_quietly(path);
    io_error("cannot write", path, error);
  }
}

void write_file_atomically(const std::filesystem::path& path, std::string_view content, Commit mode) {
  if (!path.parent_path().empty()) create_output_folder(path.parent_path());
  const auto tmp = partial_path(path);
  try {
    write_temporary_file(tmp, content);
    commit_file(tmp, path, mode);
  } catch (const OutputError& e) {
    remove_quietly(tmp);  // never leave the temporary behind
    throw OutputError(fmt::format("{}; {} was not written", e.what(), path.string()));
  }
}

void create_output_folder(const std::filesystem::path& dir) {
  std::error_code ec;
  if (std::filesystem::is_directory(dir, ec)) return;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw OutputError(fmt::format("output folder {}: cannot create it: {}", dir.string(),
                                  ec ? ec.message() : std::string("not a folder")));
}

std::size_t remove_stale_partials(const std::filesystem::path& dir) {
  std::size_t removed = 0;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    const auto mark = name.rfind(".partial-");
    if (name.empty() || name.front() != '.' || mark == std::string::npos) continue;
    const std::string digits = name.substr(mark + 9);
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) continue;
    const long pid = std::stol(digits);
    if (pid <= 0 || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // alive, or not ours to judge
    std::error_code rm;
    std::filesystem::remove_all(it->path(), rm);
    if (!rm) ++removed;
  }
  return removed;
}

}  // namespace wearscale
