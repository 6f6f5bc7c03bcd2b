#include "wearmap_case.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

#include <fmt/format.h>

namespace wearscale::app {

namespace {

// "MIN:MAX" as two numbers; InputError naming the flag otherwise.
std::pair<double, double> parse_range_text(const std::string& flag, const std::string& text) {
  const auto bad = [&]() {
    return InputError(fmt::format("{} = '{}' is not a range; allowed: MIN:MAX, e.g. 0.01:0.3", flag, text));
  };
  const auto colon = text.find(':');
  if (colon == std::string::npos) throw bad();
  auto number = [&](std::string_view s) {
    double v = 0.0;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(v)) throw bad();
    return v;
  };
  const std::string_view all(text);
  return {number(all.substr(0, colon)), number(all.substr(colon + 1))};
}

std::string key_of(const std::string& assignment) {
  const auto eq = assignment.find('=');
  std::string key = assignment.substr(0, eq);
  while (!key.empty() && std::isspace(static_cast<unsigned char>(key.back()))) key.pop_back();
  while (!key.empty() && std::isspace(static_cast<unsigned char>(key.front()))) key.erase(key.begin());
  return key;
}

}  // namespace

void add_case_options(CLI::App* cmd, WearmapCase& c, const std::string& table) {
  cmd->add_option("case", c.case_file,
                  fmt::format("Case file with a [{}] table (every flag is also a key there) and [output] dir", table));
  cmd->add_option("--set", c.overrides, fmt::format("Override a case key: --set {}.n=64 (repeatable)", table))
      ->expected(1)
      ->take_all();
  cmd->add_option("--out", c.out, "Output folder (default: [output] dir, else out/wearmap)");
  cmd->add_flag("--json", c.json, "Print one JSON object with the results, resolved parameters and files");
}

CLI::Option* add_case_flag(CLI::App* cmd, WearmapCase& c, const std::string& name, const std::string& key,
                   const std::string& help) {
  auto& slot = c.flags.emplace_back(WearmapCase::Flag{name, key, {}, false});
  return cmd->add_option(name, slot.value, fmt::format("{}: {}", help, key));
}

void add_case_range_flag(CLI::App* cmd, WearmapCase& c, const std::string& name, const std::string& key,
                         const std::string& help) {
  auto& slot = c.flags.emplace_back(WearmapCase::Flag{name, key, {}, true});
  cmd->add_option(name, slot.value, fmt::format("{}: {} = [MIN, MAX]", help, key))->type_name("MIN:MAX");
}

void add_case_switch(CLI::App* cmd, WearmapCase& c, const std::string& name, const std::string& key,
                     const std::string& value, const std::string& help) {
  auto* slot = &c.flags.emplace_back(WearmapCase::Flag{name, key, {}, false});
  cmd->add_flag_callback(name, [slot, value]() { slot->value = value; }, fmt::format("{}: {} = {}", help, key, value));
}

Config build_case(const WearmapCase& c) {
  Config cfg = c.case_file.empty() ? Config::from_string("", "<command line>") : Config::load(c.case_file);
  for (const auto& f : c.flags) {
    if (f.value.empty()) continue;
    if (f.range) {
      cfg.override_value(fmt::format("{}={}", f.key, toml_range(parse_range_text(f.name, f.value))));
    } else {
      cfg.override_value(fmt::format("{}={}", f.key, f.value));
    }
  }
  for (const auto& o : c.overrides) cfg.override_value(o);
  cfg.string_or("case.name", "wearmap");
  cfg.string_or("case.description", "");
  return cfg;
}

InputError name_flag(const WearmapCase& c, const InputError& e) {
  // Who set each key last: a flag ("--hurst 1.5"), else a --set ("--set KEY=VALUE").
  std::vector<std::pair<std::string, std::string>> setters;  // key, how
  for (const auto& f : c.flags)
    if (!f.value.empty()) setters.emplace_back(f.key, fmt::format("{} {}", f.name, f.value));
  for (const auto& o : c.overrides) setters.emplace_back(key_of(o), "--set " + o);
  const std::string msg = e.what();
  for (auto it = setters.rbegin(); it != setters.rend(); ++it) {
    const std::string needle = fmt::format("key '{}", it->first);
    for (auto p = msg.find(needle); p != std::string::npos; p = msg.find(needle, p + 1)) {
      const auto q = p + needle.size();
      if (q < msg.size() && (msg[q] == '\'' || msg[q] == '['))
        return InputError(fmt::format("{}: {}", it->second, msg.substr(p)));
    }
  }
  return e;
}

std::pair<double, double> read_range(const Config& cfg, const std::string& key, std::pair<double, double> fallback,
                                     const Range& element, const std::string& what) {
  if (!cfg.has(key)) {
    cfg.mark_used(key);
    return fallback;
  }
  const auto v = cfg.numbers(key, element);
  if (v.size() != 2 || !(v[0] < v[1]))
    throw cfg.error(key, "not a range [MIN, MAX] with MIN < MAX",
                    fmt::format("[MIN, MAX] of {} with MIN < MAX, each {}", what, element.describe()));
  return {v[0], v[1]};
}

void record(Config& cfg, const std::string& key, const std::string& toml_value) {
  cfg.override_value(fmt::format("{}={}", key, toml_value));
}

std::string toml_number(double v) { return fmt::format("{}", v); }

std::string toml_range(std::pair<double, double> r) {
  return fmt::format("[{}, {}]", toml_number(r.first), toml_number(r.second));
}

std::filesystem::path output_folder(const WearmapCase& c, const Config& cfg, const std::string& fallback) {
  const std::string dir = cfg.string_or("output.dir", fallback);
  return c.out.empty() ? std::filesystem::path(dir) : std::filesystem::path(c.out);
}

OutputLock lock_output_folder(const WearmapCase& c, const std::filesystem::path& out) {
  std::error_code ec;
  if (std::filesystem::exists(out, ec) && !std::filesystem::is_directory(out, ec))
    throw InputError(fmt::format("{} = '{}' cannot be used as an output folder (not a folder); allowed: a folder that "
                                 "can be created and written",
                                 c.out.empty() ? "output.dir" : "--out", out.string()));
  return OutputLock::folder(out, "wearscale wearmap" + (c.case_file.empty() ? "" : " " + c.case_file));
}

}  // namespace wearscale::app
