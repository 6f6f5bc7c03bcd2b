#include "wearscale/core/edit_distance.hpp"
#include "wearscale/io/config.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <map>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/text_file.hpp"
#include "wearscale/core/utf8.hpp"

namespace wearscale {

struct Config::State {
  toml::table root;
  std::string source;
  std::filesystem::path base_dir;  // relative paths in the file are relative to its folder
  std::set<std::string, std::less<>> used;
  std::map<std::string, units::Dimension, std::less<>> dimensions;  // key → the dimension it was read in (number())
  std::map<std::string, std::string, std::less<>> overridden;  // key → origin of its value
  bool collecting = false;          // collect_errors()
  std::vector<std::string> errors;  // what was recorded while collecting
  bool checked = false;             // reject_unknown_keys() passed on the whole case
  bool stop_when_checked = false;
  nlohmann::json defaults = nlohmann::json::object();  // key → the default a getter applied
};

namespace {

std::string join(std::string_view prefix, std::string_view key) {
  if (prefix.empty()) return std::string(key);
  if (key.empty()) return std::string(prefix);
  return fmt::format("{}.{}", prefix, key);
}

std::string parent_of(const std::string& key) {
  const auto dot = key.rfind('.');
  return dot == std::string::npos ? std::string() : key.substr(0, dot);
}

std::string leaf_of(const std::string& key) {
  const auto dot = key.rfind('.');
  return dot == std::string::npos ? key : key.substr(dot + 1);
}

std::string repr(const toml::node& n) {
  std::ostringstream os;
  if (auto s = n.as_string())
    os << '"' << s->get() << '"';
  else if (auto f = n.as_floating_point())
    os << fmt::format("{}", f->get());  // shortest form that reads back exactly
  else if (n.is_table())
    os << "{table}";
  else
    n.visit([&](const auto& v) { os << v; });
  return os.str();
}

std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a float";
    case toml::node_type::boolean: return "a boolean";
    default: return "a date/time";
  }
}


// The allowed value nearest to `v` (a stand-in for an out-of-range value while
// errors are collected), or nullopt when there is none (NaN, an empty range).
std::optional<double> nearest_allowed(const Range& range, double v) {
  if (std::isnan(v)) return std::nullopt;
  const double inf = std::numeric_limits<double>::infinity();
  const double lo = range.lo_open ? std::nextafter(range.lo, inf) : range.lo;
  const double hi = range.hi_open ? std::nextafter(range.hi, -inf) : range.hi;
  if (!(lo <= hi)) return std::nullopt;
  const double s = std::clamp(v, lo, hi);
  if (!range.contains(s)) return std::nullopt;
  return s;
}

nlohmann::json json_number(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";  // as to_json writes an infinite value
  return v;
}

nlohmann::json to_json_node(const toml::node& n) {
  if (auto t = n.as_table()) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [k, v] : *t) j[std::string(k.str())] = to_json_node(v);
    return j;
  }
  if (auto a = n.as_array()) {
    nlohmann::json j = nlohmann::json::array();
    for (const auto& v : *a) j.push_back(to_json_node(v));
    return j;
  }
  if (auto s = n.as_string()) return s->get();
  if (auto i = n.as_integer()) return i->get();
  if (auto f = n.as_floating_point()) {
    const double v = f->get();
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";  // JSON has no infinity
    return v;
  }
  if (auto b = n.as_boolean()) return b->get();
  return repr(n);
}

// The case's shape within Config::max_depth and Config::max_key_bytes, walked
// without recursion (a case deeper than the bound must not exhaust the stack).
void check_shape(const toml::table& root, const std::string& source, std::size_t depth = 0, std::size_t key_bytes = 0) {
  struct Visit {
    const toml::node* node;
    std::size_t depth, key_bytes;
  };
  std::vector<Visit> todo{{&root, depth, key_bytes}};
  while (!todo.empty()) {
    const Visit v = todo.back();
    todo.pop_back();
    const auto refuse = [&](const std::string& what, const std::string& allowed) {
      throw InputError(fmt::format("{}:{}: {}; allowed: {}", source, v.node->source().begin.line, what, allowed));
    };
    if (v.depth > Config::max_depth)
      refuse(fmt::format("tables and arrays nested more than {} deep", Config::max_depth),
             fmt::format("at most {} levels (the deepest key wearscale reads has 5)", Config::max_depth));
    if (v.key_bytes > Config::max_key_bytes)
      refuse(fmt::format("a key of more than {} bytes (table path and name)", Config::max_key_bytes),
             fmt::format("keys of at most {} bytes", Config::max_key_bytes));
    if (const auto* t = v.node->as_table()) {
      for (const auto& [k, child] : *t) todo.push_back({&child, v.depth + 1, v.key_bytes + k.str().size() + 1});
    } else if (const auto* a = v.node->as_array()) {
      for (const auto& child : *a) todo.push_back({&child, v.depth + 1, v.key_bytes});
    }
  }
}

}  // namespace

Config::Config(std::shared_ptr<State> state, std::string prefix) : state_(std::move(state)), prefix_(std::move(prefix)) {}
Config::Config(const Config&) = default;
Config& Config::operator=(const Config&) = default;
Config::Config(Config&&) noexcept = default;
Config& Config::operator=(Config&&) noexcept = default;
Config::~Config() = default;

Config Config::load(const std::filesystem::path& file) {
  Config cfg = from_string(read_text_file(file, "case file", max_case_file_bytes), file.string());
  cfg.state_->base_dir = file.parent_path();
  return cfg;
}

Config Config::from_string(std::string_view text, std::string source) {
  auto state = std::make_shared<State>();
  state->source = std::move(source);
  try {
    state->root = toml::parse(text, state->source);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}:{}: TOML syntax error: {}", state->source, e.source().begin.line,
                                 e.source().begin.column, e.description()));
  }
  check_shape(state->root, state->source);
  return Config(std::move(state), "");
}

void Config::override_value(std::string_view assignment, std::string_view origin) {
  if (!is_utf8(assignment))  // strings of the case reach JSON outputs, which hold UTF-8 only
    throw InputError(fmt::format("{}: {} is not valid UTF-8 (shown with U+FFFD where a byte is not); allowed: "
                                 "UTF-8 text",
                                 origin, quoted_for_message(assignment)));
  const auto eq = assignment.find('=');
  auto trim = [](std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
  };
  if (eq == std::string_view::npos || trim(assignment.substr(0, eq)).empty())
    throw InputError(fmt::format("--set {}: expected KEY=VALUE, e.g. --set scale.macro.grid=64", assignment));
  const std::string key = full_key(trim(assignment.substr(0, eq)));
  const std::string_view text = trim(assignment.substr(eq + 1));
  if (key.size() > max_key_bytes || std::count(key.begin(), key.end(), '.') >= static_cast<long>(max_depth))
    throw InputError(fmt::format("{}: a key of {} bytes and {} levels; allowed: keys of at most {} bytes and {} levels",
                                 origin, key.size(), std::count(key.begin(), key.end(), '.') + 1, max_key_bytes,
                                 max_depth));
  if (text.find_first_of("\n\r") != std::string_view::npos)
    throw InputError(fmt::format("{}: key '{}': the value spans several lines; allowed: one value per --set", origin,
                                 key));

  // The value as TOML if it parses as one, else as a bare string.
  toml::table parsed;
  bool as_toml = true;
  try {
    const std::string doc = fmt::format("v = {}", text);
    parsed = toml::parse(std::string_view(doc), std::string_view("--set"));
  } catch (const toml::parse_error&) {
    as_toml = false;
  }
  // The value itself (an array of arrays, an inline table) within the bounds too, where it goes.
  if (as_toml)
    check_shape(parsed, std::string(origin), static_cast<std::size_t>(std::count(key.begin(), key.end(), '.')),
                key.size() - 1);

  toml::table* table = &state_->root;
  std::string walked;
  std::string_view rest = key;
  while (true) {
    const auto dot = rest.find('.');
    const std::string part(rest.substr(0, dot));
    if (part.empty())
      throw InputError(fmt::format("--set {}: empty component in key '{}'", assignment, key));
    walked = join(walked, part);
    if (dot == std::string_view::npos) {
      if (as_toml)
        table->insert_or_assign(part, *parsed.get("v"));
      else
        table->insert_or_assign(part, std::string(text));
      break;
    }
    auto* node = table->get(part);
    if (node == nullptr) {
      table->insert(part, toml::table{});
      node = table->get(part);
    }
    if (!node->is_table())
      throw InputError(fmt::format("--set {}: '{}' is {}, not a table, so '{}' cannot be set", assignment,
                                   walked, type_name(*node), key));
    table = node->as_table();
    rest = rest.substr(dot + 1);
  }
  state_->overridden[key] = std::string(origin);
}

Config Config::clone() const {
  auto copy = std::make_shared<State>(*state_);
  return Config(std::move(copy), prefix_);
}

void Config::erase(std::string_view key) {
  const std::string full = full_key(key);
  const std::string parent = parent_of(full);
  toml::table* t = parent.empty() ? &state_->root : state_->root.at_path(parent).as_table();
  if (t != nullptr) t->erase(leaf_of(full));
}

std::string Config::full_key(std::string_view key) const { return join(prefix_, key); }
const std::string& Config::source() const { return state_->source; }
Config Config::section(std::string_view key) const { return Config(state_, full_key(key)); }

bool Config::has(std::string_view key) const {
  return static_cast<bool>(state_->root.at_path(full_key(key)));
}

std::vector<std::string> Config::keys(std::string_view table) const {
  std::vector<std::string> out;
  const auto full = full_key(table);
  const toml::table* t = full.empty() ? &state_->root : state_->root.at_path(full).as_table();
  if (t != nullptr)
    for (const auto& [k, v] : *t) out.emplace_back(k.str());
  return out;
}

void Config::mark_used(std::string_view key) const { state_->used.insert(full_key(key)); }

std::vector<std::string> Config::keys_read() const { return {state_->used.begin(), state_->used.end()}; }

InputError Config::error(std::string_view key, std::string_view problem, std::string_view allowed) const {
  const std::string full = full_key(key);
  if (!has(key)) {
    // A missing key is often a misspelt one: point at a close sibling.
    const std::string parent = parent_of(full), leaf = leaf_of(full);
    const toml::table* t = parent.empty() ? &state_->root : state_->root.at_path(parent).as_table();
    if (t != nullptr)
      for (const auto& [k, v] : *t)
        if (edit_distance(k.str(), leaf) <= 2) {
          const std::string found = parent.empty() ? std::string(k.str()) : parent + "." + std::string(k.str());
          return InputError::at_key(state_->source, full, "", std::string(problem),
                                    fmt::format("{} (the case has '{}': misspelt?)", allowed, found));
        }
  }
  std::string value;
  if (auto node = state_->root.at_path(full); node) value = repr(*node.node());
  return InputError::at_key(where(key), full, value, std::string(problem), std::string(allowed));
}

std::string Config::where(std::string_view key) const {
  const std::string full = full_key(key);
  // An element of an overridden array ("a.b[2]") comes from that override too.
  for (std::string k = full.substr(0, full.find('[')); !k.empty(); k = parent_of(k))
    if (const auto it = state_->overridden.find(k); it != state_->overridden.end()) return it->second;
  if (auto node = state_->root.at_path(full); node)
    return fmt::format("{}:{}", state_->source, node.node()->source().begin.line);
  return state_->source;
}

std::filesystem::path Config::path(std::string_view key) const {
  const std::string text = string(key);
  if (text.empty() || text.find('\0') != std::string::npos)
    throw error(key, "not a file name", "a file name, relative to the case file's folder");
  std::filesystem::path p(text);
  const std::string full = full_key(key);
  bool from_file = true;
  for (std::string k = full; !k.empty(); k = parent_of(k))
    if (state_->overridden.count(k) != 0) from_file = false;
  if (p.is_relative() && from_file && !state_->base_dir.empty()) p = (state_->base_dir / p).lexically_normal();
  return p;
}

namespace {
const toml::node* find(const toml::table& root, const std::string& full) { return root.at_path(full).node(); }
}  // namespace

bool Config::record(const InputError& e) const {
  if (!state_->collecting) return false;
  state_->errors.emplace_back(e.what());
  return true;
}

void Config::record_default(std::string_view key, nlohmann::json value) const {
  state_->defaults[full_key(key)] = std::move(value);
}

double Config::number(std::string_view key, const Range& range, units::Dimension dim) const {
  const std::string full = full_key(key);
  mark_used(key);
  state_->dimensions[full] = dim;
  const std::string unit = dim == units::dimensionless ? "" : " " + dim.to_string();
  const std::string allowed = range.describe() + unit;
  const toml::node* n = find(state_->root, full);
  if (n == nullptr) throw error(key, "missing required number", allowed);
  double v = 0.0;
  if (auto f = n->as_floating_point()) {
    v = f->get();
  } else if (auto i = n->as_integer()) {
    // The nearest double: an integer beyond 2^53 is not exact as a number
    // (toml++'s lossless value<double>() gives none), and the range decides.
    v = static_cast<double>(i->get());
  } else if (auto s = n->as_string(); s != nullptr && (s->get() == "inf" || s->get() == "+inf" || s->get() == "-inf")) {
    // "inf" as TOML's inf: infinity of any dimension (a bulk layer's thickness), which the range then judges;
    // a sweep value "inf" arrives as TOML's inf, so the case's key and the sweep read alike.
    v = s->get() == "-inf" ? -HUGE_VAL : HUGE_VAL;
  } else if (auto s = n->as_string()) {
    units::Quantity q{};
    try {
      q = units::parse_quantity(s->get());
    } catch (const std::invalid_argument& e) {
      throw error(key, fmt::format("cannot read a quantity: {}", e.what()), allowed);
    }
    if (!(q.dimension == dim))
      throw error(key, fmt::format("has unit of {}, expected {}", q.dimension.to_string(), dim.to_string()),
                  allowed);
    v = q.value;
  } else {
    throw error(key, fmt::format("expected a number, got {}", type_name(*n)), allowed);
  }
  v = range.snap(v);
  if (!range.contains(v)) {
    const auto e = error(key, "out of range", allowed);
    const auto stand_in = nearest_allowed(range, v);
    if (stand_in && record(e)) return *stand_in;
    throw e;
  }
  return v;
}

double Config::number_or(std::string_view key, double fallback, const Range& range, units::Dimension dim) const {
  mark_used(key);
  if (!has(key)) {
    record_default(key, json_number(fallback));
    return fallback;
  }
  try {
    return number(key, range, dim);
  } catch (const InputError& e) {
    if (record(e)) return fallback;
    throw;
  }
}

long Config::integer(std::string_view key, const Range& range) const {
  mark_used(key);
  const std::string allowed = "integer " + range.describe();
  const toml::node* n = find(state_->root, full_key(key));
  if (n == nullptr) throw error(key, "missing required integer", allowed);
  if (!n->is_integer()) throw error(key, fmt::format("expected an integer, got {}", type_name(*n)), allowed);
  const auto v = n->as_integer()->get();
  if (!range.contains(static_cast<double>(v))) {
    const auto e = error(key, "out of range", allowed);
    Range whole = range;  // the nearest integer inside
    whole.lo = std::ceil(range.lo_open ? std::nextafter(range.lo, INFINITY) : range.lo);
    whole.hi = std::floor(range.hi_open ? std::nextafter(range.hi, -INFINITY) : range.hi);
    whole.lo_open = whole.hi_open = false;
    const auto stand_in = nearest_allowed(whole, static_cast<double>(v));
    if (stand_in && std::abs(*stand_in) < 9e15 && range.contains(*stand_in) && record(e))
      return static_cast<long>(*stand_in);
    throw e;
  }
  return static_cast<long>(v);
}

long Config::integer_or(std::string_view key, long fallback, const Range& range) const {
  mark_used(key);
  if (!has(key)) {
    record_default(key, fallback);
    return fallback;
  }
  try {
    return integer(key, range);
  } catch (const InputError& e) {
    if (record(e)) return fallback;
    throw;
  }
}

bool Config::boolean(std::string_view key) const {
  mark_used(key);
  const toml::node* n = find(state_->root, full_key(key));
  if (n == nullptr) throw error(key, "missing required boolean", "true or false");
  if (!n->is_boolean()) throw error(key, fmt::format("expected a boolean, got {}", type_name(*n)), "true or false");
  return n->as_boolean()->get();
}

bool Config::boolean_or(std::string_view key, bool fallback) const {
  mark_used(key);
  if (!has(key)) {
    record_default(key, fallback);
    return fallback;
  }
  try {
    return boolean(key);
  } catch (const InputError& e) {
    if (record(e)) return fallback;
    throw;
  }
}

std::string Config::string(std::string_view key) const {
  mark_used(key);
  const toml::node* n = find(state_->root, full_key(key));
  if (n == nullptr) throw error(key, "missing required string", "a string");
  if (!n->is_string()) throw error(key, fmt::format("expected a string, got {}", type_name(*n)), "a string");
  return n->as_string()->get();
}

std::string Config::string_or(std::string_view key, std::string fallback) const {
  mark_used(key);
  if (!has(key)) {
    record_default(key, fallback);
    return fallback;
  }
  try {
    return string(key);
  } catch (const InputError& e) {
    if (record(e)) return fallback;
    throw;
  }
}

std::string Config::choice(std::string_view key, std::initializer_list<std::string_view> allowed) const {
  return choice(key, std::vector<std::string>(allowed.begin(), allowed.end()));
}

std::string Config::choice_or(std::string_view key, std::string fallback,
                              std::initializer_list<std::string_view> allowed) const {
  return choice_or(key, std::move(fallback), std::vector<std::string>(allowed.begin(), allowed.end()));
}

std::string Config::choice(std::string_view key, const std::vector<std::string>& allowed) const {
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + fmt::format("\"{}\"", a);
  mark_used(key);
  const toml::node* n = find(state_->root, full_key(key));
  if (n == nullptr) throw error(key, "missing required choice", list);
  if (!n->is_string()) throw error(key, fmt::format("expected a string, got {}", type_name(*n)), list);
  std::string v = n->as_string()->get();
  if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) throw error(key, "not a known choice", list);
  return v;
}

std::string Config::choice_or(std::string_view key, std::string fallback,
                              const std::vector<std::string>& allowed) const {
  mark_used(key);
  if (!has(key)) {
    record_default(key, fallback);
    return fallback;
  }
  try {
    return choice(key, allowed);
  } catch (const InputError& e) {
    if (record(e)) return fallback;
    throw;
  }
}

std::optional<units::Dimension> Config::dimension_of(std::string_view key) const {
  const auto it = state_->dimensions.find(full_key(key));
  if (it == state_->dimensions.end()) return std::nullopt;
  return it->second;
}

std::vector<double> Config::numbers(std::string_view key, const Range& range, units::Dimension dim) const {
  mark_used(key);
  state_->dimensions[full_key(key)] = dim;
  const std::string unit = dim == units::dimensionless ? "" : " " + dim.to_string();
  const toml::node* n = find(state_->root, full_key(key));
  const std::string allowed = "array of numbers in " + range.describe() + unit;
  if (n == nullptr) throw error(key, "missing required array", allowed);
  const toml::array* a = n->as_array();
  if (a == nullptr) throw error(key, fmt::format("expected an array, got {}", type_name(*n)), allowed);
  std::vector<double> out;
  out.reserve(a->size());
  const std::string base = full_key(key);
  for (std::size_t i = 0; i < a->size(); ++i) {
    // Reuse the scalar path (types, units, range) on each element.
    Config element(state_, "");
    out.push_back(element.number(fmt::format("{}[{}]", base, i), range, dim));
  }
  return out;
}

std::vector<std::string> Config::values_as_text(std::string_view key) const {
  mark_used(key);
  const toml::node* n = find(state_->root, full_key(key));
  if (n == nullptr) throw error(key, "missing required array", "an array of numbers or strings");
  const toml::array* a = n->as_array();
  if (a == nullptr || a->empty())
    throw error(key, "expected a non-empty array", "an array of numbers or strings");
  std::vector<std::string> out;
  for (const auto& v : *a) {
    if (auto s = v.as_string())
      out.push_back(s->get());
    else if (auto f = v.as_floating_point())
      out.push_back(fmt::format("{}", f->get()));
    else if (auto i = v.as_integer())
      out.push_back(fmt::format("{}", i->get()));
    else
      throw error(key, fmt::format("element {} is {}", repr(v), type_name(v)), "numbers or strings");
  }
  return out;
}

void Config::reject_unknown_keys() const {
  const auto& used = state_->used;
  auto is_used = [&](const std::string& key) {
    for (std::string k = key; !k.empty(); k = parent_of(k))
      if (used.count(k) != 0) return true;
    return false;
  };
  std::vector<std::string> unknown;
  auto walk = [&](auto&& self, const toml::table& t, const std::string& prefix) -> void {
    for (const auto& [k, v] : t) {
      const std::string key = join(prefix, k.str());
      if (is_used(key)) continue;
      if (auto sub = v.as_table(); sub != nullptr && !sub->empty())
        self(self, *sub, key);
      else
        unknown.push_back(key);
    }
  };
  const toml::table* start = prefix_.empty() ? &state_->root : state_->root.at_path(prefix_).as_table();
  if (start != nullptr) walk(walk, *start, prefix_);

  // Each unknown key with the keys read beside it and the closest of them.
  std::vector<std::string> messages;
  const Config root(state_, "");
  for (const auto& key : unknown) {
    const std::string parent = parent_of(key);
    std::vector<std::string> known;
    for (const auto& u : used)
      if (parent_of(u) == parent && u.find('[') == std::string::npos) known.push_back(leaf_of(u));
    std::string allowed;
    if (known.empty()) {
      allowed = parent.empty() ? "no such top-level table is read"
                               : fmt::format("nothing in [{}] is read by this case", parent);
    } else {
      std::string best;
      std::size_t best_d = 3;  // suggest only close matches
      for (const auto& k : known)
        if (auto d = edit_distance(leaf_of(key), k); d < best_d) best_d = d, best = k;
      allowed = fmt::format("keys read in [{}]: {}", parent, fmt::join(known, ", "));
      if (!best.empty()) allowed += fmt::format(" (did you mean '{}'?)", best);
    }
    messages.push_back(root.error(key, "unknown key (no component of this case reads it)", allowed).what());
  }
  if (!prefix_.empty()) {  // a part of the case: the rest may still be read
    if (messages.empty()) return;
    if (state_->collecting) {
      state_->errors.insert(state_->errors.end(), messages.begin(), messages.end());
      return;
    }
    state_->errors = messages;
    raise_collected_errors();
  }
  // The whole case: every key has been read.
  state_->errors.insert(state_->errors.end(), messages.begin(), messages.end());
  raise_collected_errors();
  state_->checked = true;
  if (state_->stop_when_checked) throw CaseChecked{};
}

void Config::collect_errors(bool on) const { state_->collecting = on; }

bool Config::has_collected_errors() const { return !state_->errors.empty(); }

namespace {
InputError error_of(const std::string& source, const std::vector<std::string>& errors) {
  if (errors.size() == 1) return InputError(errors.front());
  std::string text = fmt::format("{}: {} errors in the case:", source, errors.size());
  for (std::size_t k = 0; k < errors.size(); ++k) text += fmt::format("\n  {}. {}", k + 1, errors[k]);
  return InputError(text);
}
}  // namespace

void Config::raise_collected_errors() const {
  state_->collecting = false;
  if (state_->errors.empty()) return;
  const auto errors = std::move(state_->errors);
  state_->errors.clear();
  throw error_of(state_->source, errors);
}

InputError Config::collected_with(const std::string& last) const {
  state_->collecting = false;
  auto errors = std::move(state_->errors);
  state_->errors.clear();
  if (errors.empty()) return InputError(last);
  errors.push_back(last + " (found with the values in error above replaced by their default or nearest allowed "
                          "value; it may follow from them)");
  return error_of(state_->source, errors);
}

bool Config::fully_checked() const { return state_->checked; }

void Config::stop_when_checked(bool on) const { state_->stop_when_checked = on; }

const nlohmann::json& Config::applied_defaults() const { return state_->defaults; }

nlohmann::json Config::to_json_with_defaults() const {
  nlohmann::json j = to_json_node(state_->root);
  for (const auto& [key, value] : state_->defaults.items()) {
    if (key.find('[') != std::string::npos) continue;  // an element of an array: the array is there
    nlohmann::json* at = &j;
    std::size_t start = 0;
    for (;;) {
      const auto dot = key.find('.', start);
      const std::string part = key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
      if (dot == std::string::npos) {
        if (!at->contains(part)) (*at)[part] = value;
        break;
      }
      if (!at->contains(part)) (*at)[part] = nlohmann::json::object();
      at = &(*at)[part];
      if (!at->is_object()) break;  // a value where a table would be: the case has its own
      start = dot + 1;
    }
  }
  return j;
}

nlohmann::json Config::to_json() const {
  const std::string full = prefix_;
  if (full.empty()) return to_json_node(state_->root);
  auto n = state_->root.at_path(full);
  return n ? to_json_node(*n.node()) : nlohmann::json::object();
}

std::string Config::to_toml() const {
  std::ostringstream os;
  os << toml::toml_formatter{state_->root};
  return os.str();
}

}  // namespace wearscale
