#pragma once
// The MD shear test as case keys: a [md] table (or --set md.KEY=VALUE),
// SI numbers or unit strings, on top of a preset, read into the plain
// md::ShearTestSpec that the md library runs (md reads no case).
//
//   [md]
//   material = "Si"                 # "SiO2", or a [materials.define.<name>] with an interatomic table
//   preset = "smoke"                # or "thesis"; the keys below override it
//   pressures = ["0 GPa", "10 GPa"] # or Pa numbers: [0, 1e10]
//   lateral_size = "2.2 nm"         # box x = y, rounded to whole lattice cells
//   height = "2.2 nm"
//   shear_velocity = "100 m/s"
//   temperature = "300 K"
//   timestep = "0.001 ps"
//   strain_end = 0.6
//   window = [0.4, 0.6]             # σ_dyn = mean shear stress over this strain range
//   seed = 1
//   potential = "SiO.1990.vashishta"  cutoff = "8 Å"  lattice_constant = "7.16 Å"  (override the material's model)
//   lmp = "/usr/bin/lmp"            ranks = 2
//   cache = true                    cache_dir = "~/.cache/wearscale/lammps"
//   [md.Si]                         # keys for one material alone (a pipeline with several
//   pressures = [...]               #   materials: [scale.molecular.<material>])
//   [md.quench]                     # amorphous: temperatures = [5000, …, 300], hold_time,
//                                   # cooling_rate = "166 K/ps", final_cooling_rate, timestep, constant_volume
#include <string>

#include "wearscale/io/config.hpp"
#include "wearscale/core/key_spec.hpp"
#include "wearscale/md/shear_test.hpp"

namespace wearscale::coupling {

/// Reads every key of the `md` section of the case `root` (the material's
/// model from the built-in records or the case's [materials.define], the
/// preset, then each key that is present overrides them) and validates the
/// result; InputError naming the key for any bad value.
md::ShearTestSpec read_shear_test_spec(const Config& root);
/// The same keys read from `section` (e.g. [scale.molecular]) for a material
/// given apart with its interatomic model.
md::ShearTestSpec read_shear_test_spec(const Config& section, const std::string& material,
                                       const materials::InteratomicModel& model);

/// The rows of the shear test's keys in the table `prefix` ("md",
/// "scale.molecular"): the preset, the protocol, the model's overrides, the
/// melt-quench and a table per material; one key table declares them and
/// read_shear_test_spec reads them.
Schema shear_test_schema(const std::string& prefix);
/// The rows of [md]: its material, then shear_test_schema("md").
Schema md_schema();

}  // namespace wearscale::coupling
