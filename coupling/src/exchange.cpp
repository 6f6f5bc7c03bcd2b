#include "wearscale/coupling/exchange.hpp"

namespace wearscale::coupling {

nlohmann::json Provenance::to_json() const {
  return {{"scale", scale}, {"backend", backend}, {"parameters", parameters}, {"version", version}};
}

std::vector<Key> Exchange::keys() const {
  std::vector<Key> out;
  for (const auto& [k, e] : entries_) out.push_back(k);
  return out;
}

const Exchange::Entry& Exchange::entry(const Key& key) const {
  auto it = entries_.find(key);
  if (it == entries_.end()) throw std::logic_error("exchange: nothing provided " + key.to_string());
  return it->second;
}

}  // namespace wearscale::coupling
