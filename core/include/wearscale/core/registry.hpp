#pragma once
// The one registry of wearscale's extension points: named factories of scale
// backends (a kind and a name: "macro", "hertz"), studies and DEM contact
// laws (a name alone). Each extension registers itself by one line beside its
// class (WEARSCALE_BACKEND, WEARSCALE_STUDY, WEARSCALE_CONTACT_LAW: thin
// spellings over add()); the build collects those lines into the function
// that fills the registry (cmake/WearscaleRegistrations.cmake), never by
// static initialisers, which a static library drops.
//
// Generic over what it makes and what it shows, so core knows nothing of the
// layers above: Info holds `name` (and `kind` when entries have kinds) and
// words its own "unknown name" message (Info::unknown). A scale backend's
// entry holds its keys too (BackendInfo::keys, from its key table), so a
// backend is one file: its class, its key table and its registration.
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/key_spec.hpp"

namespace wearscale {

/// The entry of `known` closest in spelling to `name` (at most two edits), or "".
std::string closest_name(const std::vector<std::string>& known, const std::string& name);

/// What `wearscale backends` shows about a scale backend.
struct BackendInfo {
  std::string kind;     ///< scale kind: "molecular", "nano", "macro", ...
  std::string name;     ///< backend name within the kind: "table", "analytic", ...
  std::string summary;  ///< one line: what it computes and from what (with thesis section)
  std::vector<std::string> consumes;
  std::vector<std::string> provides;
  /// The rows of the keys it reads in its [scale.<kind>] table, named
  /// "scale.<kind>.<key>", as its key table declares them (empty: it reads
  /// none there; [materials] is declared apart).
  std::function<Schema()> keys = {};
  std::string id() const { return kind + "/" + name; }
  /// The message of an unknown kind or backend, listing the known ones.
  static std::string unknown(const std::string& kind, const std::string& name, const std::vector<std::string>& kinds,
                             const std::vector<std::string>& known);
};

template <class Info>
concept KindedInfo = requires(const Info& i) { i.kind; };

/// Named factories of Product made from Args..., each shown by its Info.
template <class Info, class Product, class... Args>
class NamedRegistry {
 public:
  using Factory = std::function<std::unique_ptr<Product>(Args...)>;

  /// Registers an entry; registering the same kind/name twice is a programming error.
  void add(Info info, Factory factory) {
    auto key = std::make_pair(kind_of(info), info.name);
    if (entries_.count(key) != 0)
      throw std::logic_error("registered twice: " + (key.first.empty() ? "" : key.first + "/") + key.second);
    entries_.emplace(std::move(key), Entry{std::move(info), std::move(factory)});
  }

  bool contains(const std::string& kind, const std::string& name) const { return entries_.count({kind, name}) != 0; }
  bool contains(const std::string& name) const { return contains({}, name); }

  const Info& info(const std::string& kind, const std::string& name) const { return lookup(kind, name).info; }
  const Info& info(const std::string& name) const { return lookup({}, name).info; }

  /// Makes an entry; an unknown kind or name is bad input (InputError) whose
  /// message lists what is registered (Info::unknown).
  std::unique_ptr<Product> create(const std::string& kind, const std::string& name, Args... args) const
    requires KindedInfo<Info>
  {
    return lookup(kind, name).factory(std::forward<Args>(args)...);
  }
  std::unique_ptr<Product> create(const std::string& name, Args... args) const
    requires(!KindedInfo<Info>)
  {
    return lookup({}, name).factory(std::forward<Args>(args)...);
  }

  std::vector<std::string> kinds() const {
    std::vector<std::string> out;
    for (const auto& [key, e] : entries_)
      if (out.empty() || out.back() != key.first) out.push_back(key.first);
    return out;
  }

  /// The names of a kind (of every entry, for a registry without kinds), sorted.
  std::vector<std::string> names(const std::string& kind = {}) const {
    std::vector<std::string> out;
    for (const auto& [key, e] : entries_)
      if (key.first == kind) out.push_back(key.second);
    return out;
  }

  /// Every entry, sorted by kind then name.
  std::vector<Info> list() const {
    std::vector<Info> out;
    for (const auto& [key, e] : entries_) out.push_back(e.info);
    return out;
  }

 private:
  struct Entry {
    Info info;
    Factory factory;
  };

  static std::string kind_of(const Info& info) {
    if constexpr (KindedInfo<Info>)
      return info.kind;
    else
      return {};
  }

  const Entry& lookup(const std::string& kind, const std::string& name) const {
    if (auto it = entries_.find({kind, name}); it != entries_.end()) return it->second;
    throw InputError(Info::unknown(kind, name, kinds(), names(kind)));
  }

  std::map<std::pair<std::string, std::string>, Entry> entries_;
};

/// The scale backends' registry (coupling::ScaleRegistry): entries with a kind.
template <class Product, class... Args>
using Registry = NamedRegistry<BackendInfo, Product, Args...>;

}  // namespace wearscale
