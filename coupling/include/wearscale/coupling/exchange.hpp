#pragma once
// The typed blackboard through which scales hand quantities to each other;
// every entry remembers which scale and backend produced it, with what.
#include <any>
#include <map>
#include <stdexcept>
#include <string>
#include <typeinfo>
#include <vector>

#include <nlohmann/json.hpp>

#include "wearscale/coupling/quantity.hpp"

namespace wearscale::coupling {

/// Who produced an exchanged quantity and from what.
struct Provenance {
  std::string scale;           ///< scale kind: "molecular", "nano", "macro"
  std::string backend;         ///< backend name
  nlohmann::json parameters;   ///< the backend's resolved case section
  std::string version = WEARSCALE_VERSION;
  nlohmann::json to_json() const;
};

class Exchange {
 public:
  /// Stores `value` under `key`; a key is written once (two providers is a pipeline error).
  template <class T>
  void put(const Key& key, T value, Provenance provenance) {
    if (entries_.count(key) != 0)
      throw std::logic_error("exchange: " + key.to_string() + " provided twice (by " +
                             entries_.at(key).provenance.backend + " and " + provenance.backend + ")");
    entries_.emplace(key, Entry{std::any(std::move(value)), std::move(provenance)});
  }

  /// The value of `key` as a T; a missing key or a wrong type is a programming
  /// error of the pipeline (the pipeline checks providers before running).
  template <class T>
  const T& get(const Key& key) const {
    const auto& e = entry(key);
    if (const T* v = std::any_cast<T>(&e.value)) return *v;
    throw std::logic_error("exchange: " + key.to_string() + " holds " + e.value.type().name() + ", asked for " +
                           typeid(T).name());
  }

  bool contains(const Key& key) const { return entries_.count(key) != 0; }
  const Provenance& provenance(const Key& key) const { return entry(key).provenance; }
  std::vector<Key> keys() const;

 private:
  struct Entry {
    std::any value;
    Provenance provenance;
  };
  const Entry& entry(const Key& key) const;
  std::map<Key, Entry> entries_;
};

}  // namespace wearscale::coupling
