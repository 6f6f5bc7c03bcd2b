#pragma once
// A shear-strength study: the §9.3.1 shear test run with LAMMPS at each
// pressure of a spec (for SiO2 after one melt–quench shared by all
// pressures), each run looked up in / stored to the result cache, and the
// outcome as a materials::StrengthTable with its provenance.
#include <filesystem>
#include <functional>
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

/// Spreads independent runs: calls task(k) for every k in [0, count) (each
/// returns a short text) wherever it likes, and returns the texts in task
/// order where they are gathered, std::nullopt elsewhere. The studies give a
/// farm over MPI ranks (coupling/shear_farm.hpp); the solver knows no MPI.
using RunMap = std::function<std::optional<std::vector<std::string>>(
    std::size_t count, const std::function<std::string(std::size_t)>& task)>;

/// Runs (or reads from the cache) every pressure of `spec`, the pressures
/// (and, first, the SiO2 quench) through `map` (empty: in order, here). Where
/// `map` gathers nothing the study comes back without quench and points.
/// The outcome does not depend on the map: each run's figures are read back
/// from its cache entry. InputError for a bad spec or a missing lmp/potential;
/// NumericalError for a failed run or unusable output (naming the run folder).
ShearStudy run_shear_study(const ShearTestSpec& spec, const RunMap& map = {});

/// The study as a strength table: pressures and strengths in Pa, provenance
/// (source, material, LAMMPS version, potential and cutoff, box and atoms,
/// temperature, thermostat, velocity and shear rate, strain window, seeds,
/// quench, date, cost per point, and per-point details).
materials::StrengthTable strength_table(const ShearStudy& study);

}  // namespace wearscale::md
