#pragma once
// The Si/oxide pin-on-disc case swept over the oxide thickness, written once
// into a test's folder as `sweep.toml` (the MPI and job-array sweep tests).
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.hpp"

/// Writes `dir/sweep.toml` unless it exists: cases/pin_on_disc_si_oxide.toml
/// with a [sweep] of materials.layer.thickness over `values` (a TOML array's
/// inside, e.g. `0, 1e-6, "inf"`) into friction_vs_thickness.csv.
inline void write_oxide_sweep_case(const std::filesystem::path& dir, const std::string& values) {
  if (std::filesystem::exists(dir / "sweep.toml")) return;
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "sweep.toml") << slurp(std::filesystem::path(WEARSCALE_SOURCE_DIR) /
                                             "cases/pin_on_disc_si_oxide.toml")
                                    << "\n[sweep]\nkey = \"materials.layer.thickness\"\nvalues = [" << values
                                    << "]\ntable = \"friction_vs_thickness.csv\"\n";
}
