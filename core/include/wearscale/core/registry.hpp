#pragma once
// A registry of named backends: (scale kind, backend name) → factory.
//
// Generic over what it makes, so core knows nothing of the scales the
// coupling layer defines. Registration is explicit (one call per backend in
// one list), never by static initialisers, which a static library drops.
#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/errors.hpp"

namespace wearscale {

/// What `wearscale backends` shows about a backend.
struct BackendInfo {
  std::string kind;     ///< scale kind: "molecular", "nano", "macro", ...
  std::string name;     ///< backend name within the kind: "table", "analytic", ...
  std::string summary;  ///< one line: what it computes and from what (with thesis section)
  std::vector<std::string> consumes;
  std::vector<std::string> provides;
  std::string id() const { return kind + "/" + name; }
};

template <class Product, class... Args>
class Registry {
 public:
  using Factory = std::function<std::unique_ptr<Product>(Args...)>;

  /// Registers a backend; registering the same kind/name twice is a programming error.
  void add(BackendInfo info, Factory factory) {
    auto key = std::make_pair(info.kind, info.name);
    if (entries_.count(key) != 0)
      throw std::logic_error("backend registered twice: " + info.id());
    entries_.emplace(std::move(key), Entry{std::move(info), std::move(factory)});
  }

  bool contains(const std::string& kind, const std::string& name) const {
    return entries_.count({kind, name}) != 0;
  }

  const BackendInfo& info(const std::string& kind, const std::string& name) const {
    return lookup(kind, name).info;
  }

  /// Makes a backend; an unknown kind or name is bad input and the message
  /// lists what is registered.
  std::unique_ptr<Product> create(const std::string& kind, const std::string& name, Args... args) const {
    return lookup(kind, name).factory(std::forward<Args>(args)...);
  }

  std::vector<std::string> kinds() const {
    std::vector<std::string> out;
    for (const auto& [key, e] : entries_)
      if (out.empty() || out.back() != key.first) out.push_back(key.first);
    return out;
  }

  std::vector<std::string> names(const std::string& kind) const {
    std::vector<std::string> out;
    for (const auto& [key, e] : entries_)
      if (key.first == kind) out.push_back(key.second);
    return out;
  }

  /// Every backend, sorted by kind then name.
  std::vector<BackendInfo> list() const {
    std::vector<BackendInfo> out;
    for (const auto& [key, e] : entries_) out.push_back(e.info);
    return out;
  }

 private:
  struct Entry {
    BackendInfo info;
    Factory factory;
  };

  const Entry& lookup(const std::string& kind, const std::string& name) const {
    if (auto it = entries_.find({kind, name}); it != entries_.end()) return it->second;
    const auto known = names(kind);
    if (known.empty())
      throw InputError(fmt::format("unknown scale kind '{}'; known kinds: {}", kind, fmt::join(kinds(), ", ")));
    throw InputError(fmt::format("unknown {} backend '{}'; known {} backends: {}", kind, name, kind,
                                 fmt::join(known, ", ")));
  }

  std::map<std::pair<std::string, std::string>, Entry> entries_;
};

}  // namespace wearscale
