#include "wearscale/core/edit_distance.hpp"
#include "wearscale/io/config.hpp"

#include <algorithm>
#include <cmath>
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

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

struct Config::State {
  toml::table root;
  std::string source;
  std::filesystem::path base_dir;  // relative paths in the file are relative to its folder
  std::set<std::string, std::less<>> used;
  std::map<std::string, units::Dimension, std::less<>> dimensions;  // key → the dimension it was read in (number())
  std::map<std::string, std::string, std::less<>> overridden;  // key → origin of its value
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
  if (!range.contains(v)) throw error(key, "out of range", allowed);
  return v;
}

double Config::number_or(std::string_view key, double fallback, const Range& range, units::Dimension dim) const {
  mark_used(key);
  return has(key) ? number(key, range, dim) : fallback;
}

long Config::integer(std::string_view key, const Range& range) const {
  mark_used(key);
  const std::string allowed = "integer " + range.describe();
  const toml::node* n = find(state_->root, full_key(key));
  if (n == nullptr) throw error(key, "missing required integer", allowed);
  if (!n->is_integer()) throw error(key, fmt::format("expected an integer, got {}", type_name(*n)), allowed);
  const auto v = n->as_integer()->get();
  if (!range.contains(static_cast<double>(v))) throw error(key, "out of range", allowed);
  return static_cast<long>(v);
}

long Config::integer_or(std::string_view key, long fallback, const Range& range) const {
  mark_used(key);
  return has(key) ? integer(key, range) : fallback;
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
  return has(key) ? boolean(key) : fallback;
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
  return has(key) ? string(key) : fallback;
}

std::string Config::choice(std::string_view key, std::initializer_list<std::string_view> allowed) const {
  std::string list;
  for (auto a : allowed) list += (list.empty() ? "" : ", ") + fmt::format("\"{}\"", a);
  mark_used(key);
  const toml::node* n = find(state_->root, full_key(key));
  if (n == nullptr) throw error(key, "missing required choice", list);
  if (!n->is_string()) throw error(key, fmt::format("expected a string, got {}", type_name(*n)), list);
  std::string v = n->as_string()->get();
  if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) throw error(key, "not a known choice", list);
  return v;
}

std::string Config::choice_or(std::string_view key, std::string fallback,
                              std::initializer_list<std::string_view> allowed) const {
  mark_used(key);
  return has(key) ? choice(key, allowed) : fallback;
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
  if (start == nullptr) return;
  walk(walk, *start, prefix_);
  if (unknown.empty()) return;

  const std::string key = unknown.front();
  const std::string parent = parent_of(key);
  std::vector<std::string> known;
  for (const auto& u : used)
    if (parent_of(u) == parent && u.find('[') == std::string::npos) known.push_back(leaf_of(u));
  std::string allowed;
  if (known.empty()) {
    allowed = parent.empty() ? "no such top-level table is read" : fmt::format("nothing in [{}] is read by this case", parent);
  } else {
    std::string best;
    std::size_t best_d = 3;  // suggest only close matches
    for (const auto& k : known)
      if (auto d = edit_distance(leaf_of(key), k); d < best_d) best_d = d, best = k;
    allowed = fmt::format("keys read in [{}]: {}", parent, fmt::join(known, ", "));
    if (!best.empty()) allowed += fmt::format(" (did you mean '{}'?)", best);
  }
  Config root(state_, "");
  throw root.error(key, "unknown key (no component of this case reads it)", allowed);
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
