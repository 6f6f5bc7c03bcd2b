#pragma once
// A contact study described by a case ([contact] table): the surface (a
// file, a generated rough surface and/or a sphere), the material, the load;
// solves it and writes fields, micro-contacts and headline figures.
//
//   [contact]
//   surface = "rough.h5"        # or [contact.rough] / [contact.sphere] on grid × size
//   e_star = "37.6 GPa"         # or young + poisson (rigid surface on an elastic flat)
//   mean_pressure = "1 MPa"     # or normal_load (per cell) or interference
//   boundary = "periodic"       # or "free": the grid is a window on an isolated body
//                               # (zero-padded half-space; frictionless only)
//
// Frictional contact (Appendix A) adds, with poisson given (and young or e_star):
//   friction = "coulomb"        # "none" (default) | "coulomb" | "tresca"
//   friction_coefficient = 0.5  # μ (A.2), Coulomb
//   shear_strength = "250 MPa"  # σ_m,T (A.3), Tresca
//   tangential_pressure = "2 MPa"   # mean p_x (or tangential_load, a force on the cell)
//   tensile_strength = "500 MPa"    # optional σ_m: crack initiation (4.25) per micro-contact
//   stress_depths = ["1 um", "5 um"]  # optional: σ_I and τ_m fields below the surface
// and writes p_N, p_x, p_y, the stick/slip map, slips, displacements and the
// surface σ_I, σ_III, τ_m (plus the requested depths).
#include <filesystem>

#include <nlohmann/json.hpp>

#include "wearscale/core/config.hpp"

namespace wearscale::bem {

/// Reads every key of `[contact]` (InputError on any bad value), solves, and
/// writes contact.h5 (+ .xdmf), clusters.csv into `output_dir`. Returns the
/// headline figures {name: {value, unit, description}} and the files written.
nlohmann::json run_contact_study(const Config& config, const std::filesystem::path& output_dir);

}  // namespace wearscale::bem
