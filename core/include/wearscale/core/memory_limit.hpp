#pragma once
// The memory a run may use, checked before it allocates: a grid, a dataset
// or a particle system too large for the machine is refused as bad input
// (exit 2, naming what needs how much) instead of dying later of
// std::bad_alloc or the kernel's out-of-memory killer.
//
// The limit is the smallest of: the machine's physical memory, the memory
// limit of the process' cgroup (containers, batch jobs), the address-space
// and data-segment limits (ulimit -v, ulimit -d), and WEARSCALE_MEMORY_LIMIT
// ("4 GiB", "500 MB", or bytes) when set.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace wearscale {

struct MemoryLimit {
  double bytes = 0.0;
  std::string source;  ///< "physical memory", "cgroup limit", "ulimit -v", "WEARSCALE_MEMORY_LIMIT"
};

/// The limit for this process, read once.
const MemoryLimit& memory_limit();

/// InputError unless `bytes` (a double: products of user sizes may exceed
/// 2^64) fit within the limit: "<what> needs 32 GiB, more than the 24 GiB
/// this process may use (physical memory); <advice>". NaN or infinite bytes
/// are refused too.
void require_memory(double bytes, const std::string& what, const std::string& advice = {});

/// What require_memory() is asked for in this thread while a tally lives:
/// the memory a case declares before it runs (`wearscale check`).
class MemoryTally {
 public:
  MemoryTally();
  ~MemoryTally();
  MemoryTally(const MemoryTally&) = delete;
  MemoryTally& operator=(const MemoryTally&) = delete;
  /// Each request: what, bytes.
  const std::vector<std::pair<std::string, double>>& requests() const { return requests_; }
  /// Their sum.
  double bytes() const;

 private:
  friend void require_memory(double, const std::string&, const std::string&);
  std::vector<std::pair<std::string, double>> requests_;
  MemoryTally* outer_ = nullptr;
};

/// "1.5 GiB", "298 GiB": binary units, three significant digits.
std::string format_bytes(double bytes);

/// Bytes from "4 GiB", "500 MB", "2e9"; a negative value if it cannot be read.
double parse_bytes(const std::string& text);

}  // namespace wearscale
