#pragma once
// Materials a case defines: the [materials.define.<name>] tables.
#include "wearscale/io/config.hpp"
#include "wearscale/materials/material.hpp"

namespace wearscale {

/// Adds every [materials.define.<name>] table of `root` to `library` (all keys
/// read and range-checked; a user material may override a built-in one by name).
void define_materials_from(materials::MaterialLibrary& library, const Config& root);

}  // namespace wearscale
