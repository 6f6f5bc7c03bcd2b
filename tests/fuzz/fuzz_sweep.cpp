// Fuzzes the case runner's checks on the way to a run: the overrides (--set)
// and a [sweep] (key, values, table) applied to a case, and every run's
// scales built from the result, without running or writing anything. Input:
// lines "set KEY=VALUE" (the overrides), then the case file's text. Any
// input either passes or raises InputError (the message naming what); a
// crash, another exception or a sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "wearscale/core/errors.hpp"
#include "wearscale/io/config.hpp"
#include "wearscale/studies/runner.hpp"

using namespace wearscale;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  studies::RunOptions options;
  options.case_file = "fuzz.toml";
  options.output_dir = "fuzz-out";  // never created: check_case writes nothing
  while (text.substr(0, 4) == "set ") {
    const auto end = text.find('\n');
    options.overrides.emplace_back(text.substr(4, end == std::string_view::npos ? end : end - 4));
    if (end == std::string_view::npos || options.overrides.size() > 16) return 0;
    text.remove_prefix(end + 1);
  }
  const std::string body(text);
  try {
    (void)studies::check_case([&] { return Config::from_string(body, "fuzz.toml"); }, options);
  } catch (const InputError&) {
  }
  return 0;
}
