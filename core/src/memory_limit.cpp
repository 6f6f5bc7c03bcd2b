#include "wearscale/core/memory_limit.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string_view>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale {

namespace {

// The cgroup v2 limit (memory.max) or v1 limit of this process, 0 if none.
double cgroup_limit() {
  for (const char* file : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
    std::ifstream in(file);
    std::string text;
    if (!(in >> text) || text == "max") continue;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() && v > 0.0 && v < 1e18) return v;  // v1 reports ~2^63 for "no limit"
  }
  return 0.0;
}

double rlimit_of(int resource) {
  rlimit r{};
  if (::getrlimit(resource, &r) != 0 || r.rlim_cur == RLIM_INFINITY) return 0.0;
  return static_cast<double>(r.rlim_cur);
}

MemoryLimit find_limit() {
  MemoryLimit limit;
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  limit.bytes = pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 1e18;
  limit.source = "physical memory";
  auto lower = [&](double bytes, const char* source) {
    if (bytes > 0.0 && bytes < limit.bytes) limit = {bytes, source};
  };
  lower(cgroup_limit(), "cgroup memory limit");
  lower(rlimit_of(RLIMIT_AS), "ulimit -v");
  lower(rlimit_of(RLIMIT_DATA), "ulimit -d");
  if (const char* env = std::getenv("WEARSCALE_MEMORY_LIMIT"); env != nullptr && *env != '\0') {
    const double v = parse_bytes(env);
    if (v > 0.0) {
      limit = {v, "WEARSCALE_MEMORY_LIMIT"};  // an explicit budget, e.g. a batch job's share
    }
  }
  return limit;
}

}  // namespace

const MemoryLimit& memory_limit() {
  static const MemoryLimit limit = find_limit();
  return limit;
}

std::string format_bytes(double bytes) {
  static constexpr const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  if (!std::isfinite(bytes)) return fmt::format("{} B", bytes);
  double v = bytes;
  int u = 0;
  while (std::abs(v) >= 1024.0 && u < 6) v /= 1024.0, ++u;
  if (std::abs(v) >= 1024.0) return fmt::format("{:.3g} B", bytes);
  return u == 0 ? fmt::format("{:.0f} B", v) : fmt::format("{:.3g} {}", v, units[u]);
}

double parse_bytes(const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  const double v = std::strtod(begin, &end);
  if (end == begin || !std::isfinite(v) || v <= 0.0) return -1.0;
  std::string_view unit(end);
  while (!unit.empty() && std::isspace(static_cast<unsigned char>(unit.front()))) unit.remove_prefix(1);
  while (!unit.empty() && std::isspace(static_cast<unsigned char>(unit.back()))) unit.remove_suffix(1);
  static constexpr std::pair<std::string_view, double> units[] = {
      {"", 1.0},           {"B", 1.0},     {"kB", 1e3},          {"MB", 1e6},          {"GB", 1e9},
      {"TB", 1e12},        {"KiB", 1024.0}, {"MiB", 1048576.0}, {"GiB", 1073741824.0}, {"TiB", 1099511627776.0},
      {"K", 1024.0},       {"M", 1048576.0}, {"G", 1073741824.0}};
  for (const auto& [name, factor] : units)
    if (unit == name) return v * factor;
  return -1.0;
}

namespace {
thread_local MemoryTally* current_tally = nullptr;
}  // namespace

MemoryTally::MemoryTally() : outer_(current_tally) { current_tally = this; }
MemoryTally::~MemoryTally() { current_tally = outer_; }

double MemoryTally::bytes() const {
  double sum = 0.0;
  for (const auto& r : requests_) sum += r.second;
  return sum;
}

void require_memory(double bytes, const std::string& what, const std::string& advice) {
  if (current_tally != nullptr) current_tally->requests_.emplace_back(what, bytes);
  const MemoryLimit& limit = memory_limit();
  if (std::isfinite(bytes) && bytes <= limit.bytes) return;
  throw InputError(fmt::format("{} needs {}, more than the {} this process may use ({}){}", what, format_bytes(bytes),
                               format_bytes(limit.bytes), limit.source, advice.empty() ? "" : "; " + advice));
}

}  // namespace wearscale
