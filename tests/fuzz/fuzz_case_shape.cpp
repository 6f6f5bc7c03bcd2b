// Fuzzes the case reader's bounds on its shape: the input describes a case
// (how deep its tables, dotted keys, arrays and inline tables nest, how long
// its keys are, how many entries a table has) rather than being one, so the
// fuzzer reaches depths of thousands and keys of tens of kilobytes at once.
// The case is read as a file and as --set overrides: either it loads, within
// Config::max_depth and Config::max_key_bytes, or it is refused with
// InputError; and either way within the harness's time (a 20 000-level path
// used to take minutes).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "wearscale/core/errors.hpp"
#include "wearscale/io/config.hpp"

using namespace wearscale;

namespace {

// Bytes as small instructions.
struct Reader {
  const std::uint8_t* data;
  std::size_t size, at = 0;
  unsigned next() { return at < size ? data[at++] : 0u; }
  unsigned wide() { return next() | (next() << 8); }
};

std::string key_of(Reader& in) {
  const unsigned length = 1 + in.wide() % 3000;
  return std::string(length, static_cast<char>('a' + in.next() % 26));
}

// The deepest nesting and the longest dotted key of a loaded case, walked again here.
void check_loaded(const Config& cfg, const std::string& table, std::size_t depth) {
  if (depth > Config::max_depth) std::abort();
  for (const auto& k : cfg.keys(table)) {
    const std::string full = table.empty() ? k : table + "." + k;
    if (full.size() > Config::max_key_bytes) std::abort();
    check_loaded(cfg, full, depth + 1);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Reader in{data, size};
  std::string text = "[case]\nname = \"shape\"\n";
  std::vector<std::string> overrides;
  const unsigned pieces = 1 + in.next() % 6;
  for (unsigned p = 0; p < pieces && text.size() < (std::size_t{4} << 20); ++p) {
    const unsigned depth = in.wide() % 25000;
    std::string path = key_of(in);
    switch (in.next() % 5) {
      case 0:  // a table header [a.a.a...]
        for (unsigned d = 1; d < depth; ++d) path += "." + std::string(1 + in.next() % 3, 'a');
        text += "[" + path + "]\nv = 1\n";
        break;
      case 1:  // a dotted key a.a.a = 1 in the root
        for (unsigned d = 1; d < depth; ++d) path += ".b";
        text = path + " = 1\n" + text;
        break;
      case 2:  // nested arrays
        text += "[t" + std::to_string(p) + "]\nv = " + std::string(depth % 5000, '[') + "1" +
                std::string(depth % 5000, ']') + "\n";
        break;
      case 3:  // nested inline tables
        text += "[u" + std::to_string(p) + "]\nv = ";
        for (unsigned d = 0; d < depth % 2000; ++d) text += "{ w = ";
        text += "1";
        for (unsigned d = 0; d < depth % 2000; ++d) text += " }";
        text += "\n";
        break;
      default:  // a --set of a deep key and value
        for (unsigned d = 1; d < depth % 4000; ++d) path += ".c";
        overrides.push_back(path + "=" + std::string(depth % 300, '[') + "2" + std::string(depth % 300, ']'));
    }
  }
  try {
    Config cfg = Config::from_string(text, "shape.toml");
    for (const auto& o : overrides) {
      try {
        cfg.override_value(o);
      } catch (const InputError&) {
      }
    }
    check_loaded(cfg, "", 0);
    (void)cfg.to_toml();
  } catch (const InputError&) {
  }
  return 0;
}
