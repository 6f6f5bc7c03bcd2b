// Fuzzes the case-file loader: any bytes either load or raise InputError,
// and every typed getter on every key of a loaded case either returns or
// raises InputError (units, ranges, arrays, overrides, unknown keys, JSON/TOML
// export). Anything else — a crash, another exception, UB — is a bug.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "wearscale/core/errors.hpp"
#include "wearscale/io/config.hpp"

using namespace wearscale;

namespace {
template <class F>
void input_error_only(F&& f) {
  try {
    f();
  } catch (const InputError&) {
  }
}

// Every getter on every key, recursively (bounded depth and count).
void exercise(const Config& cfg, const std::string& table, int depth, int& budget) {
  if (depth > 8) return;
  for (const auto& key : cfg.keys(table)) {
    if (--budget < 0) return;
    const std::string k = table.empty() ? key : table + "." + key;
    input_error_only([&] { (void)cfg.number(k, Range::positive(), units::length); });
    input_error_only([&] { (void)cfg.number(k, Range::any()); });
    input_error_only([&] { (void)cfg.number(k, Range::non_negative().or_infinite(), units::time); });
    input_error_only([&] { (void)cfg.integer(k, Range::closed(8, 4096)); });
    input_error_only([&] { (void)cfg.boolean(k); });
    input_error_only([&] { (void)cfg.string(k); });
    input_error_only([&] { (void)cfg.choice(k, {"explicit", "adaptive"}); });
    input_error_only([&] { (void)cfg.numbers(k, Range::any(), units::pressure); });
    input_error_only([&] { (void)cfg.values_as_text(k); });
    input_error_only([&] { (void)cfg.error(k, "fuzz", "anything"); });
    exercise(cfg, k, depth + 1, budget);
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // The first line, if it looks like KEY=VALUE, is also tried as a --set override.
  const auto newline = text.find('\n');
  try {
    Config cfg = Config::from_string(text, "fuzz.toml");
    if (newline != std::string_view::npos && text.substr(0, newline).find('=') != std::string_view::npos)
      input_error_only([&] { cfg.override_value(text.substr(0, newline)); });
    int budget = 200;
    exercise(cfg, "", 0, budget);
    (void)cfg.to_json().dump();
    (void)cfg.to_toml();
    input_error_only([&] { cfg.reject_unknown_keys(); });
  } catch (const InputError&) {
  }
  return 0;
}
