// Runs a libFuzzer harness without libFuzzer (the default build, any compiler):
// on every file named on the command line (or in a folder named there), then on
// COUNT inputs made from them by seeded random byte changes, insertions and
// cuts (`--random COUNT --seed S`; S defaults to a new one each run, printed).
// The harness's own checks (std::abort) and any crash fail the test, as under
// the fuzzer; CI thus tries the seeds and new inputs of each harness's class
// every run, in seconds.
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {
std::vector<std::uint8_t> bytes_of(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
}  // namespace

int main(int argc, char** argv) {
  std::vector<std::vector<std::uint8_t>> seeds;
  long count = 0;
  std::uint64_t seed = static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
  if (const char* s = std::getenv("WEARSCALE_HOSTILE_SEED"); s != nullptr && *s != '\0') seed = std::strtoull(s, nullptr, 10);
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--random" && k + 1 < argc) {
      count = std::strtol(argv[++k], nullptr, 10);
    } else if (arg == "--seed" && k + 1 < argc) {
      seed = std::strtoull(argv[++k], nullptr, 10);
    } else if (std::filesystem::is_directory(arg)) {
      for (const auto& e : std::filesystem::directory_iterator(arg)) seeds.push_back(bytes_of(e.path()));
    } else {
      seeds.push_back(bytes_of(arg));
    }
  }
  if (seeds.empty()) seeds.push_back({});
  for (const auto& s : seeds) LLVMFuzzerTestOneInput(s.data(), s.size());
  std::cout << "replayed " << seeds.size() << " seed(s); " << count << " random inputs with seed " << seed
            << " (--seed " << seed << " replays them)" << std::endl;
  std::mt19937_64 rng(seed);
  for (long n = 0; n < count; ++n) {
    std::vector<std::uint8_t> input = seeds[rng() % seeds.size()];
    const int edits = 1 + static_cast<int>(rng() % 6);
    for (int e = 0; e < edits; ++e) {
      const auto at = input.empty() ? 0 : rng() % (input.size() + 1);
      switch (rng() % 3) {
        case 0: input.insert(input.begin() + static_cast<long>(at), static_cast<std::uint8_t>(rng())); break;
        case 1:
          if (at < input.size()) input[at] = static_cast<std::uint8_t>(rng());
          break;
        default:
          if (at < input.size()) input.erase(input.begin() + static_cast<long>(at));
      }
    }
    LLVMFuzzerTestOneInput(input.data(), input.size());
  }
  return 0;
}
