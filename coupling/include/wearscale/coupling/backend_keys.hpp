#pragma once
// The keys of each scale backend's [scale.<kind>] table, as its registry
// entry holds them (BackendInfo::keys, from its key table): what `wearscale
// help pipeline`, the pipeline study's schema and docs/keys.md list per
// backend; and the keys of [materials] the scales read.
#include <string>

#include "wearscale/core/key_spec.hpp"

namespace wearscale::coupling {

/// The rows of backend kind/name: "scale.<kind>.backend", then its keys
/// ("scale.<kind>.<key>"). InputError for a backend that is not registered.
Schema backend_schema(const std::string& kind, const std::string& name);
/// The keys of [materials] the scales read (pin, disc, layer.material,
/// layer.thickness), named "materials.<key>".
Schema materials_schema();

}  // namespace wearscale::coupling
