#pragma once
// The present moment as an ISO 8601 UTC timestamp, "2026-12-01T20:13:23Z",
// for provenance attributes and lock files.
#include <chrono>
#include <ctime>
#include <string>

namespace wearscale {

inline std::string utc_now() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

}  // namespace wearscale
