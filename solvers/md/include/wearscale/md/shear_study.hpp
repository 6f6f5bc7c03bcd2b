#pragma once
// A shear-strength study: the §9.3.1 shear test run with LAMMPS at each
// pressure of a spec (for an amorphous sample after one melt–quench shared by
// all pressures), each run looked up in / stored to the result cache, and the
// outcome as a materials::StrengthTable with its provenance.
//
// Before any pressure point the study checks that the sample is the solid
// the potential describes: the Young's modulus and Poisson's ratio of the
// sample as built (elastic_constants.hpp, at 0 K) against the potential's own
// — its ideal lattice relaxed to zero stress — or, for an amorphous sample,
// against the published values the model gives; more than the tolerance
// (10 %) apart, or a mechanically unstable sample, is refused (InputError)
// before the shear runs.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "wearscale/materials/strength_table.hpp"
#include "wearscale/md/elastic_constants.hpp"
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
  double h_gap = 0.0;            ///< distance between the walls' inner faces after compression [m]
  /// Elastic shear modulus of the sheared sample: the slope of τ over strains
  /// up to spec.modulus_strain (or strain_end), times h_gap/h0 (the shear
  /// spreads over the gap) [Pa]; NaN if fewer than 3 rows lie there.
  double shear_modulus = 0.0;
};

/// The sample's elastic moduli against the potential's (see above).
struct ElasticCheck {
  ElasticModuli reference;          ///< the potential's own, or the published ones (isotropic)
  ElasticModuli sample;             ///< of the sample as built, at 0 K
  std::string reference_source;
  bool isotropic = false;           ///< amorphous: isotropic E, ν compared; crystal: E_z, ν_zx
  double reference_lattice_constant = 0.0;  ///< crystal: the ideal lattice relaxed at 0 K [m]
  double sample_pressure = 0.0;     ///< mean normal stress −tr(σ)/3 of the unstrained sample at 0 K [Pa]
  double young_error = 0.0;         ///< |E_sample − E_ref| / E_ref
  double poisson_error = 0.0;       ///< |ν_sample − ν_ref| / max(|ν_ref|, 0.1)
  double tolerance = 0.10;
  std::optional<RunRecord> reference_run;  ///< crystal only
  RunRecord sample_run;
  bool passed() const {
    return sample.stable() && reference.stable() && young_error <= tolerance && poisson_error <= tolerance;
  }
  /// "E_z = 66.7 GPa (ref 66.9, 0.3 %), nu_zx = 0.419 (ref 0.419, 0.0 %)".
  std::string summary() const;
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
  std::optional<ElasticCheck> elastic;
  std::vector<ShearPoint> points;
};

/// Spreads independent runs: calls task(k) for every k in [0, count) (each
/// returns a short text) wherever it likes, and returns the texts in task
/// order where they are gathered, std::nullopt elsewhere. The studies give a
/// farm over MPI ranks (coupling/shear_farm.hpp); the solver knows no MPI.
using RunMap = std::function<std::optional<std::vector<std::string>>(
    std::size_t count, const std::function<std::string(std::size_t)>& task)>;

/// Runs (or reads from the cache) every pressure of `spec`: first the quench
/// of an amorphous sample, then the elastic check (one task: InputError if
/// the sample fails it), then the pressures, each stage through `map`
/// (empty: in order, here). Where `map` gathers nothing the study comes back
/// without quench, check and points.
/// The outcome does not depend on the map: each run's figures are read back
/// from its cache entry. InputError for a bad spec or a missing lmp/potential;
/// NumericalError for a failed run or unusable output (naming the run folder).
ShearStudy run_shear_study(const ShearTestSpec& spec, const RunMap& map = {});

/// The study as a strength table: pressures and strengths in Pa, provenance
/// (source, material, LAMMPS version, command, potential with its SHA-256 and
/// cutoff, box and atoms, elastic check, temperature, thermostat, velocity and
/// shear rate, strain window, seeds, quench, date, cost per point, and
/// per-point details).
materials::StrengthTable strength_table(const ShearStudy& study);

}  // namespace wearscale::md
