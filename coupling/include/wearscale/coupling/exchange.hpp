#pragma once
// The typed blackboard through which scales hand quantities to each other;
// every entry remembers which scale and backend produced it, with what.
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "wearscale/core/version.hpp"
#include "wearscale/coupling/quantity.hpp"

namespace wearscale::coupling {

/// Who produced an exchanged quantity and from what.
struct Provenance {
  std::string scale;           ///< scale kind: "molecular", "nano", "macro"
  std::string backend;         ///< backend name
  nlohmann::json parameters;   ///< the backend's resolved case section
  std::string version = wearscale::version();  // a function, not the macro: the installed header needs no define
  nlohmann::json to_json() const;
};

class Exchange {
 public:
  /// Stores `value` as quantity Q of `subject`; a key is written once (two
  /// providers is a pipeline error). The value's type is Q's (quantity.hpp).
  template <Quantity Q>
  void put(std::string subject, QuantityType<Q> value, Provenance provenance) {
    Key key{Q, std::move(subject)};
    if (entries_.count(key) != 0)
      throw std::logic_error("exchange: " + key.to_string() + " provided twice (by " +
                             entries_.at(key).provenance.backend + " and " + provenance.backend + ")");
    entries_.emplace(std::move(key), Entry{Value(std::in_place_index<index(Q)>, std::move(value)), std::move(provenance)});
  }

  /// Quantity Q of `subject`; a missing key is a programming error of the
  /// pipeline (it checks providers before running).
  template <Quantity Q>
  const QuantityType<Q>& get(const std::string& subject) const {
    return std::get<index(Q)>(entry({Q, subject}).value);
  }

  bool contains(const Key& key) const { return entries_.count(key) != 0; }
  const Provenance& provenance(const Key& key) const { return entry(key).provenance; }
  std::vector<Key> keys() const;

 private:
  static constexpr std::size_t index(Quantity q) { return static_cast<std::size_t>(q); }
  // One alternative per quantity, in the enum's order.
  using Value = std::variant<QuantityType<Quantity::ShearStrength>, QuantityType<Quantity::InterfaceLaw>,
                             QuantityType<Quantity::MacroResult>>;
  static_assert(std::variant_size_v<Value> == quantity_count, "every Quantity has its type in Exchange::Value");
  struct Entry {
    Value value;
    Provenance provenance;
  };
  const Entry& entry(const Key& key) const;
  std::map<Key, Entry> entries_;
};

}  // namespace wearscale::coupling
