#pragma once
// A normal contact study described by a case ([contact] table): the surface
// (a file, a generated rough surface and/or a sphere), the material, the
// load; solves it and writes fields, micro-contacts and headline figures.
//
//   [contact]
//   surface = "rough.h5"        # or [contact.rough] / [contact.sphere] on grid × size
//   e_star = "37.6 GPa"         # or young + poisson (rigid surface on an elastic flat)
//   mean_pressure = "1 MPa"     # or normal_load (per cell) or interference
#include <filesystem>

#include <nlohmann/json.hpp>

#include "wearscale/core/config.hpp"

namespace wearscale::bem {

/// Reads every key of `[contact]` (InputError on any bad value), solves, and
/// writes contact.h5 (+ .xdmf), clusters.csv into `output_dir`. Returns the
/// headline figures {name: {value, unit, description}} and the files written.
nlohmann::json run_contact_study(const Config& config, const std::filesystem::path& output_dir);

}  // namespace wearscale::bem
