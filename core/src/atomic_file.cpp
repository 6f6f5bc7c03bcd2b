#include "wearscale/core/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>

namespace wearscale {

namespace {
[[noreturn]] void io_error(const std::string& what, const std::filesystem::path& p) {
  throw std::runtime_error(fmt::format("{} {}: {}", what, p.string(), std::strerror(errno)));
}

void fsync_path(const std::filesystem::path& p, int flags) {
  const int fd = ::open(p.c_str(), flags);
  if (fd < 0) return;  // a folder we cannot open (odd file systems): rename is still atomic
  ::fsync(fd);
  ::close(fd);
}
}  // namespace

std::filesystem::path partial_path(const std::filesystem::path& final_path) {
  const auto name = fmt::format(".{}.partial-{}", final_path.filename().string(), ::getpid());
  return final_path.parent_path() / name;
}

void commit_file(const std::filesystem::path& partial, const std::filesystem::path& final_path) {
  fsync_path(partial, O_RDONLY);
  if (::rename(partial.c_str(), final_path.c_str()) != 0) io_error("cannot rename to", final_path);
  const auto dir = final_path.parent_path().empty() ? std::filesystem::path(".") : final_path.parent_path();
  fsync_path(dir, O_RDONLY | O_DIRECTORY);
}

void write_file_atomically(const std::filesystem::path& path, std::string_view content) {
  if (!path.parent_path().empty()) std::filesystem::create_directories(path.parent_path());
  const auto tmp = partial_path(path);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) io_error("cannot write", tmp);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) {
      std::filesystem::remove(tmp);
      io_error("cannot write", tmp);
    }
  }
  try {
    commit_file(tmp, path);
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);  // never leave the temporary behind
    throw;
  }
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
