#include "wearscale/io/laid_out_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <new>
#include <string>

#include <fmt/format.h>

#include "hdf5_lock.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/io/hdf5_file.hpp"

namespace wearscale {

namespace {

// The child: lays the file out under `partial`, sends the offsets (then an
// error message, if any) on `report`, and ends without running the parent's
// exit handlers (HDF5's, MPI's): status 0, or 1 with the message.
[[noreturn]] void lay_out_in_child(const std::filesystem::path& final_path, const std::filesystem::path& partial,
                                   Commit mode, const std::function<std::vector<std::uint64_t>(H5Writer&)>& lay_out,
                                   int report) {
  for (int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) ::signal(s, SIG_DFL);  // a crash is the verdict
  new (&detail::hdf5_mutex()) std::recursive_mutex();  // the only thread left: the parent's lock made anew
  std::string message;
  try {
    H5Writer h5(final_path, mode, H5Storage::Disk, partial);
    const std::vector<std::uint64_t> offsets = lay_out(h5);
    h5.hand_over();
    const std::uint64_t count = offsets.size();
    std::string bytes(reinterpret_cast<const char*>(&count), sizeof count);
    bytes.append(reinterpret_cast<const char*>(offsets.data()), offsets.size() * sizeof(std::uint64_t));
    for (std::size_t done = 0; done < bytes.size();) {
      const ssize_t w = ::write(report, bytes.data() + done, bytes.size() - done);
      if (w <= 0) ::_exit(2);
      done += static_cast<std::size_t>(w);
    }
    ::_exit(0);  // no destructors, no exit handlers: the parent goes on
  } catch (const std::exception& e) {  // the writer removed the temporary file on its way out
    message = e.what();
  } catch (...) {
    message = "unknown failure";
  }
  const auto n = std::min<std::size_t>(message.size(), 16000);
  if (::write(report, message.data(), n) < 0) ::_exit(2);
  ::_exit(1);
}

}  // namespace

LaidOutFile::LaidOutFile(std::filesystem::path final_path,
                         const std::function<std::vector<std::uint64_t>(H5Writer&)>& lay_out, Commit mode)
    : final_(std::move(final_path)), partial_(partial_path(final_)), mode_(mode) {
  if (!final_.parent_path().empty()) create_output_folder(final_.parent_path());
  const auto fail = [&](const std::string& why) {
    std::error_code ec;
    std::filesystem::remove(partial_, ec);
    return OutputError(fmt::format("{}; {} was not written", why, final_.string()));
  };
  int report[2] = {-1, -1};
  if (::pipe2(report, O_CLOEXEC) != 0) throw fail(fmt::format("cannot make a pipe: {}", std::strerror(errno)));
  pid_t pid = -1;
  {
    std::lock_guard lock(detail::hdf5_mutex());  // no other thread inside HDF5 while the child is made
    pid = ::fork();
    if (pid == 0) {
      ::close(report[0]);
      lay_out_in_child(final_, partial_, mode_, lay_out, report[1]);
    }
  }
  ::close(report[1]);
  std::string text;
  if (pid > 0) {
    char buffer[4096];
    for (ssize_t n; (n = ::read(report[0], buffer, sizeof buffer)) != 0;) {
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) break;
      text.append(buffer, static_cast<std::size_t>(n));
    }
  }
  ::close(report[0]);
  if (pid < 0) {  // no child possible (process or memory limits): lay it out here, as H5Writer would
    H5Writer h5(final_, mode_, H5Storage::Disk, partial_);
    offsets_ = lay_out(h5);
    h5.hand_over();
    return;
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status))
    throw fail(fmt::format("the HDF5 library crashed writing {} (signal {}, {})", partial_.string(), WTERMSIG(status),
                           ::strsignal(WTERMSIG(status))));
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    if (text.empty()) throw fail(fmt::format("the HDF5 library failed writing {}", partial_.string()));
    std::error_code ec;
    std::filesystem::remove(partial_, ec);
    throw OutputError(text);  // the writer's own message names the file
  }
  std::uint64_t count = 0;
  if (text.size() < sizeof count) throw fail("the process that wrote " + partial_.string() + " reported nothing");
  std::memcpy(&count, text.data(), sizeof count);
  if (text.size() != sizeof count + count * sizeof(std::uint64_t))
    throw fail("the process that wrote " + partial_.string() + " reported a wrong layout");
  offsets_.resize(count);
  std::memcpy(offsets_.data(), text.data() + sizeof count, count * sizeof(std::uint64_t));
}

LaidOutFile::~LaidOutFile() {
  if (committed_) return;
  std::error_code ec;
  std::filesystem::remove(partial_, ec);
}

void LaidOutFile::commit() {
  if (committed_) return;
  try {
    commit_file(partial_, final_, mode_);
  } catch (const OutputError& e) {
    throw OutputError(fmt::format("{}; {} was not written", e.what(), final_.string()));
  }
  committed_ = true;
}

}  // namespace wearscale
