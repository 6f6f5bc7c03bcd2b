#pragma once
// The keys of each scale backend's [scale.<kind>] table, as its key table
// declares them (io/key_table.hpp): what `wearscale help pipeline`, the
// pipeline study's schema and docs/keys.md list per backend.
#include <functional>
#include <string>

#include "wearscale/io/key_spec.hpp"

namespace wearscale::coupling {

/// Registers the schema of backend kind/name (from its WEARSCALE_BACKEND body).
void add_backend_keys(const std::string& kind, const std::string& name, std::function<Schema()> schema);
/// The rows of backend kind/name, named "scale.<kind>.<key>"; empty for one
/// that declares no key table.
Schema backend_schema(const std::string& kind, const std::string& name);
/// The keys of [materials] the scales read (pin, disc, layer.material,
/// layer.thickness), named "materials.<key>".
Schema materials_schema();
/// Whether backend kind/name declares its keys in a key table.
bool has_backend_keys(const std::string& kind, const std::string& name);

}  // namespace wearscale::coupling
