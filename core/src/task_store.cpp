#include "wearscale/core/task_store.hpp"

#include <fstream>
#include <mutex>
#include <sstream>
#include <utility>

#include <fmt/format.h>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/sha256.hpp"
#include "wearscale/core/task_farm.hpp"

namespace wearscale::mpi {

namespace {
thread_local TaskStore* g_current = nullptr;
constexpr const char* kMagic = "wearscale-task 1";
}  // namespace

TaskStore::TaskStore(std::filesystem::path dir, Mode mode, std::size_t shard, std::size_t shards, std::string case_id)
    : dir_(std::move(dir)),
      mode_(mode),
      shard_(shard),
      shards_(shards == 0 ? 1 : shards),
      case_id_(std::move(case_id)),
      previous_(g_current) {
  g_current = this;
}

TaskStore::~TaskStore() { g_current = previous_; }

TaskStore* TaskStore::current() { return g_current; }

std::filesystem::path TaskStore::file_of(const std::string& identity, const char* extension) const {
  return dir_ / (sha256_hex(identity).substr(0, 32) + extension);
}

std::filesystem::path TaskStore::log_path(const std::string& identity, const std::string& name) const {
  std::string file;
  for (const char c : name) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.';
    if (plain)
      file += c;
    else if (!file.empty() && file.back() != '_')
      file += '_';
  }
  if (file.size() > 80) file.resize(80);
  return dir_.parent_path() / "logs" / fmt::format("{}-{}.log", file, sha256_hex(identity).substr(0, 8));
}

std::optional<TaskResult> TaskStore::find(const std::string& identity) const {
  const auto file = file_of(identity, ".task");
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::string header;
  std::getline(in, header);
  std::istringstream fields(header);
  std::string magic_a, magic_b, digest;
  TaskResult r;
  std::string body_digest;
  fields >> magic_a >> magic_b >> digest >> r.rank >> r.threads >> r.seconds >> body_digest;
  if (!fields || magic_a + " " + magic_b != kMagic || digest != sha256_hex(identity)) {
    log::warn("{}: not a task result of this run (ignored; the task runs again)", file.string());
    return std::nullopt;
  }
  const auto start = in.tellg();
  in.seekg(0, std::ios::end);
  const auto end = in.tellg();
  in.seekg(start);
  r.text.resize(static_cast<std::size_t>(end - start));
  if (!in.read(r.text.data(), static_cast<std::streamsize>(r.text.size())) || sha256_hex(r.text) != body_digest) {
    log::warn("{}: a damaged task result (ignored; the task runs again)", file.string());
    return std::nullopt;
  }
  r.status = TaskResult::Status::Done;
  return r;
}

void TaskStore::keep(const std::string& identity, const TaskResult& result) const {
  if (result.status != TaskResult::Status::Done) return;
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (!case_id_.empty()) {
    // Rank 0 keeps its own results and its workers' from two threads: the
    // case's mark is written once, under a lock (its temporary file is named
    // by the process, so two threads writing it at once collide).
    static std::mutex case_mark;
    std::lock_guard guard(case_mark);
    if (!std::filesystem::exists(dir_ / "case.txt", ec))
      write_file_atomically(dir_ / "case.txt", case_id_ + "\n", Commit::Now);
  }
  // The header: what it is, whose result, where and how long it ran, the result's own digest.
  std::string content = fmt::format("{} {} {} {} {:.17g} {}\n", kMagic, sha256_hex(identity), result.rank,
                                    result.threads, result.seconds, sha256_hex(result.text));
  content += result.text;
  write_file_atomically(file_of(identity, ".task"), content, Commit::Now);
}

void TaskStore::keep(const std::string& identity, std::string text, double seconds) const {
  TaskResult r;
  r.status = TaskResult::Status::Done;
  r.text = std::move(text);
  r.seconds = seconds;
  keep(identity, r);
}

void TaskStore::discard() const {
  std::error_code ec;
  std::filesystem::remove_all(dir_, ec);
  if (ec) log::warn("{}: could not remove the kept tasks of the completed run ({})", dir_.string(), ec.message());
}

std::string TaskStore::case_of(const std::filesystem::path& dir) {
  std::ifstream in(dir / "case.txt");
  std::string id;
  std::getline(in, id);
  return id;
}

bool TaskStore::holds_tasks(const std::filesystem::path& dir) {
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec))
    if (e.path().extension() == ".task") return true;
  return false;
}

}  // namespace wearscale::mpi
