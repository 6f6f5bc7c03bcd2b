#pragma once
// The materials a case names in [materials] (pin, disc, layer), resolved
// against the built-in and case-defined records.
#include <string>
#include <vector>

#include "wearscale/core/config.hpp"
#include "wearscale/materials/material.hpp"

namespace wearscale::coupling {

/// Built-in materials plus every [materials.define.<name>] of the case.
materials::MaterialLibrary material_library(const Config& root);

/// Distinct names of [materials] pin, disc and layer.material, in that order;
/// InputError (naming the key) for a name the library does not know.
std::vector<std::string> case_materials(const Config& root, const materials::MaterialLibrary& library);

}  // namespace wearscale::coupling
