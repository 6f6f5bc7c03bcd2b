// Fuzzes `wearscale merge` on the values of a shard's summary: two shards of a
// small pin-on-disc sweep are run once; each input then replaces headline
// figures of one run's summary.json (a name it picks, a value it chooses:
// NaN as null, negatives, huge numbers, strings, bit patterns) and merges.
// Either the merge refuses (InputError, OutputError) or every figure it
// merged is within the bounds of a computed one: a summary changed by hand is
// never merged into a result.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/studies/runner.hpp"

using namespace wearscale;
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::stringstream ss;
  ss << std::ifstream(p).rdbuf();
  return ss.str();
}

const char* kCase = R"(
[case]
name = "merge-fuzz"
[materials]
pin = "SiO2"
disc = "Si"
layer = { material = "SiO2", thickness = "1 um" }
[scale.molecular]
backend = "table"
data = "thesis"
[scale.nano]
backend = "analytic"
[scale.macro]
backend = "bem-pin-on-disc"
grid = 8
distance = 0.0004
[run]
fft_planning = "estimate"
[sweep]
key = "materials.layer.thickness"
values = [0, 1e-6]
)";

// The shards' folder, run once; and the intact summary of the run the inputs change.
struct Shards {
  fs::path dir, summary;
  std::string intact;
};

const Shards& shards() {
  static const Shards s = [] {
    log::set_level(log::Level::Silent);
    Shards out;
    out.dir = fs::temp_directory_path() / ("wearscale-fuzz-merge-" + std::to_string(::getpid()));
    fs::remove_all(out.dir);
    fs::create_directories(out.dir);
    static fs::path made;  // removed when the harness exits
    made = out.dir;
    std::atexit([] {
      std::error_code ec;
      fs::remove_all(made, ec);
    });
    std::ofstream(out.dir / "case.toml") << kCase;
    for (const char* task : {"1/2", "2/2"}) {
      studies::RunOptions o;
      o.case_file = out.dir / "case.toml";
      o.output_dir = out.dir / "shards";
      o.task = task;
      (void)studies::run_case(o);
    }
    out.summary = out.dir / "shards" / "thickness=1e-06" / "summary.json";
    out.intact = slurp(out.summary);
    return out;
  }();
  return s;
}

nlohmann::json value_of(const std::uint8_t* data, std::size_t size, std::size_t& at) {
  const std::uint8_t kind = at < size ? data[at++] : 0;
  switch (kind % 6) {
    case 0: return nullptr;
    case 1: return -5.0;
    case 2: return "0.8";
    case 3: return 1e300;
    case 4: return -1e-300;
    default: {
      std::uint64_t bits = 0;
      for (int b = 0; b < 8; ++b) bits = (bits << 8) | (at < size ? data[at++] : 0);
      double v;
      std::memcpy(&v, &bits, sizeof v);
      return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Shards& s = shards();
  auto j = nlohmann::json::parse(s.intact);
  std::size_t at = 0;
  const unsigned changes = size > 0 ? 1 + data[at++] % 3 : 0;
  std::vector<std::string> names;
  for (const auto& [name, r] : j["results"].items()) names.push_back(name);
  for (unsigned c = 0; c < changes && at < size; ++c) {
    const std::string& name = names[data[at++] % names.size()];  // before the value: it reads on from `at`
    j["results"][name]["value"] = value_of(data, size, at);
  }
  std::ofstream(s.summary) << j.dump(2) << "\n";
  std::error_code ec;
  fs::remove(s.dir / "shards" / "summary.json", ec);
  try {
    const auto merged = studies::merge_shards(s.dir / "shards", "wearscale merge (fuzz)");
    for (const auto& run : merged.runs)
      for (const auto& [name, r] : run.results.items()) {
        const double v = r["value"].get<double>();
        // What a merge accepts is a result: finite, worn volumes and μ not negative.
        if (!std::isfinite(v)) std::abort();
        if ((name == "pin_wear" || name == "disc_wear" || name.rfind("mu_", 0) == 0) && v < 0.0) std::abort();
      }
  } catch (const InputError&) {
  }
  return 0;
}
