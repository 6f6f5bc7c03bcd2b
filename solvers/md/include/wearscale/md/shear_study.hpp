#pragma once
// A shear-strength study: the §9.3.1 shear test run with LAMMPS at each
// pressure of a spec (for SiO2 after one melt–quench shared by all
// pressures), each run looked up in / stored to the result cache, and the
// outcome as a materials::StrengthTable with its provenance.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "wearscale/materials/strength_table.hpp"
#include "wearscale/md/shear_test.hpp"
#include "wearscale/md/thermo_parser.hpp"

namespace wearscale::md {

/// What one LAMMPS run was and cost.
struct RunRecord {
  std::filesystem::path folder;  ///< cache entry holding deck, log, outputs
  std::string key;               ///< its cache key
  bool cached = false;           ///< read from the cache (lmp not called)
  double wall_seconds = 0.0;     ///< cost of the original run
  int ranks = 1;                 ///< MPI ranks of the original run
  std::string date;              ///< UTC date of the original run
};

struct ShearPoint {
  double pressure = 0.0;         ///< imposed p_N [Pa]
  RunRecord run;
  ShearCurve curve;
  ShearStrength strength;
  long atoms = 0;
  double lx = 0.0, ly = 0.0, h0 = 0.0;  ///< box and sheared height after compression [m]
};

struct QuenchRecord {
  RunRecord run;
  long atoms = 0;
  double density = 0.0;     ///< after the quench [kg/m³]
  double lx = 0.0, lz = 0.0;
};

struct ShearStudy {
  ShearTestSpec spec;
  std::filesystem::path lmp;
  std::string lammps_version;
  std::filesystem::path potential_source;  ///< the installed file it was made from
  std::string potential_sha256;            ///< of the file the runs read
  std::optional<QuenchRecord> quench;
  std::vector<ShearPoint> points;
};

/// Runs (or reads from the cache) every pressure of `spec`. InputError for a
/// bad spec or a missing lmp/potential; NumericalError for a failed run or
/// unusable output (naming the run folder).
ShearStudy run_shear_study(const ShearTestSpec& spec);

/// The study as a strength table: pressures and strengths in Pa, provenance
/// (source, material, LAMMPS version, potential and cutoff, box and atoms,
/// temperature, thermostat, velocity and shear rate, strain window, seeds,
/// quench, date, cost per point, and per-point details).
materials::StrengthTable strength_table(const ShearStudy& study);

}  // namespace wearscale::md
