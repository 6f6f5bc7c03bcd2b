#pragma once
// The materials a case names in [materials] (pin, disc, layer), resolved
// against the built-in and case-defined records.
#include <string>
#include <vector>

#include "wearscale/coupling/scale.hpp"
#include "wearscale/io/config.hpp"
#include "wearscale/io/key_table.hpp"
#include "wearscale/materials/material.hpp"
#include "wearscale/materials/strength_law.hpp"

namespace wearscale::coupling {

/// The keys of [materials] (besides define.<name>): the bodies of the
/// pin-on-disc test and the disc's oxide layer.
struct CaseMaterialKeys {
  std::string pin, disc;
  std::string layer_material;   ///< default: the disc's material
  double layer_thickness = 0.0;  ///< 0: no layer (no [materials.layer] table)
};
const KeyTable<CaseMaterialKeys>& case_material_keys();

/// [scale.molecular] outside, of the backends that give strengths from a
/// table (molecular/table, molecular/lammps): a pressure outside the table.
struct StrengthLawKeys {
  materials::OutsideTable outside = materials::OutsideTable::Error;
};
const KeyTable<StrengthLawKeys>& strength_law_keys();

/// Built-in materials plus every [materials.define.<name>] of the case.
materials::MaterialLibrary material_library(const Config& root);

/// Distinct names of [materials] pin, disc and layer.material, in that order;
/// InputError (naming the key) for a name the library does not know.
std::vector<std::string> case_materials(const Config& root, const materials::MaterialLibrary& library);

/// Provides ShearStrength(material): stores the table in run.h5 under
/// /molecular/<material> with its provenance lines, and puts the law in the
/// exchange with `provenance`.
void publish_strength(Exchange& exchange, RunContext& ctx, const std::string& material, materials::StrengthLaw law,
                      Provenance provenance);

}  // namespace wearscale::coupling
