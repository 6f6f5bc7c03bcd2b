#pragma once
// The seed of a hostile-input generator: WEARSCALE_HOSTILE_SEED if set (to
// replay a failure), else a new one each run, so that every CI run tries new
// inputs of the known classes. The test prints it; a failure names it.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

inline std::uint64_t hostile_seed() {
  static const std::uint64_t seed = [] {
    if (const char* s = std::getenv("WEARSCALE_HOSTILE_SEED"); s != nullptr && *s != '\0')
      return static_cast<std::uint64_t>(std::strtoull(s, nullptr, 10));
    return static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count() % 1000000007);
  }();
  return seed;
}

/// A generator for one class, seeded from hostile_seed() and the class's name (so classes draw independently).
inline std::mt19937_64 hostile_generator(const std::string& which) {
  const std::uint64_t seed = hostile_seed() ^ std::hash<std::string>{}(which);
  std::cout << "[ hostile  ] " << which << ": WEARSCALE_HOSTILE_SEED=" << hostile_seed() << " replays it\n";
  return std::mt19937_64(seed);
}

template <class T>
const T& pick(std::mt19937_64& rng, const std::vector<T>& choices) {
  return choices[std::uniform_int_distribution<std::size_t>(0, choices.size() - 1)(rng)];
}
