#pragma once
// Materials a case defines: the [materials.define.<name>] tables — the
// record (elastic constants, density, surface energy, ideal strengths) and,
// optionally, its interatomic model for the MD shear test
// ([materials.define.<name>.interatomic]: pair style, potential file,
// elements, masses, crystal structure and lattice constant, amorphous or not).
//
// Each key is declared once, in material_keys(): its type, allowed range,
// unit, default and meaning, which the reader checks values against and the
// studies' schemas (`--help`, docs/keys.md) list.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "wearscale/core/range.hpp"
#include "wearscale/core/units.hpp"
#include "wearscale/io/config.hpp"
#include "wearscale/materials/material.hpp"

namespace wearscale {

/// One key of a [materials.define.<name>] table.
struct MaterialKey {
  std::string key;       ///< relative to the table: "young", "interatomic.pair_style"
  std::string type;      ///< "number", "list", "string", "choice", "path", "boolean"
  Range range;           ///< numbers (each element of a list)
  units::Dimension dimension = units::dimensionless;
  std::string unit;      ///< SI unit as text ("Pa", "m", "K"; "g/mol" for masses; "1"; "" for text)
  std::string allowed;   ///< allowed values in words (choices, grammars); "" = range.describe()
  std::string fallback;  ///< default as text; "" = required (or required when its table is given)
  std::string doc;       ///< one line
};

/// Every key of [materials.define.<name>], in the order the docs list them.
const std::vector<MaterialKey>& material_keys();

/// A potential-file key: a bare file name is the file beside the case file if
/// there is one, else the name as given (md looks it up in LAMMPS' potentials
/// folder); a name with a folder is a path relative to the case file.
std::filesystem::path potential_file(const Config& c, std::string_view key);

/// Adds every [materials.define.<name>] table of `root` to `library` (all keys
/// read and range-checked; a user material may override a built-in one by
/// name). An interatomic table is validated as a whole
/// (materials::validate): element names and the potential's file name to a
/// grammar safe in a LAMMPS deck. InputError naming file, key and value.
void define_materials_from(materials::MaterialLibrary& library, const Config& root);

}  // namespace wearscale
