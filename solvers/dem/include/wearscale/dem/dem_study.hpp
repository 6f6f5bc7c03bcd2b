#pragma once
// The DEM studies a user runs from the command line (`wearscale dem ...`),
// configured by the [dem] table of a case (flags map onto its keys): the
// patch tests of §6.2, the sheared junction of §6.3, the sheared rough
// surfaces of §7.2 and the loose particles trapped between flat surfaces of
// §7.3. Each validates every key before it starts, writes its outputs under
// `out`, and returns a summary {results: {name: {value, unit, description}},
// files: [...]}.
//
// Given a Checkpointer, a study saves its state there as it goes (owner
// "dem/<study>", with the position of its snapshot file) and continues from
// the state the checkpointer restored: a killed run resumed gives the same
// outputs bit for bit (one thread). Without one it still stops on SIGINT.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "wearscale/core/checkpoint.hpp"
#include "wearscale/core/config.hpp"
#include "wearscale/dem/cohesive_material.hpp"

namespace wearscale::dem {

/// The DEM targets named by dem.material: "table-6.4" (the unitless
/// patch-test targets of Table 6.4) or a material of the case's library
/// (Si, SiO2, [materials.define.*]); dem.poisson, dem.restitution and
/// dem.scaling_exponent override or complete them.
CohesiveMaterial dem_material(const Config& root);

/// [dem.patch_test]: lattice, d0, length, width, load, strengths, ...
nlohmann::json run_patch_test_study(const Config& root, const std::filesystem::path& out,
                                    Checkpointer* checkpoints = nullptr);

/// [dem.junction]: diameter, d0, largest, velocity, pressure, ...
/// Writes the force history (CSV, HDF5) and OVITO-readable snapshots.
nlohmann::json run_junction_study(const Config& root, const std::filesystem::path& out,
                                  Checkpointer* checkpoints = nullptr);

/// [dem.rough_shear] (§7.2): d0, largest, length, depth, height, roughness
/// (Sa/L), hurst, velocity, pressure, sliding_distance, ...
/// Writes the history (forces, worn count, Sa; CSV, HDF5) and OVITO-readable
/// snapshots with a worn column.
nlohmann::json run_rough_shear_study(const Config& root, const std::filesystem::path& out,
                                     Checkpointer* checkpoints = nullptr);

/// [dem.trapped_particles] (§7.3): count, diameter, d0, largest, length,
/// depth, height, velocity, pressure, sliding_distance, ...
/// Writes the history (CSV, HDF5) and OVITO-readable snapshots with a worn column.
nlohmann::json run_trapped_particles_study(const Config& root, const std::filesystem::path& out,
                                           Checkpointer* checkpoints = nullptr);

}  // namespace wearscale::dem
