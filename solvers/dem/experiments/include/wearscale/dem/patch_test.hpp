#pragma once
// The patch tests of thesis §6.2: a sample L × L × W between two rigid walls
// (periodic across the other two axes) loaded to measure the elastic
// constants (confined compression σ_yy, then σ_xx and ε_yy give C11, C12,
// hence E and ν) and the strengths (walls pulled apart or sheared at a
// constant strain rate; the peak virial stress).
#include <functional>
#include <optional>
#include <string>

#include "wearscale/dem/cohesive_material.hpp"
#include "wearscale/dem/run_checkpoints.hpp"

namespace wearscale::dem {

struct PatchTestSpec {
  /// The bounds of the sample and its loading, one check for every caller
  /// (run_patch_test refuses outside them; the CLI's keys are read with them):
  /// L in [6, 400] d0, W in [1.25, 100] d0 (at least the largest particle; an
  /// HCP cell is √(8/3) d0), a time step in (0, 1) Δt_c, a strain rate in
  /// (0, 1e-2), at least 1000 elastic steps.
  static constexpr double min_length = 6.0, max_length = 400.0;
  static constexpr double min_width = 1.25, max_width = 100.0;
  static constexpr double max_strain_rate = 1e-2;
  static constexpr long min_elastic_steps = 1000;

  CohesiveMaterial material;
  double d0 = 0.0;             ///< particle diameter (HCP) or mode of the sizes (amorphous)
  bool amorphous = false;      ///< HCP lattice when false
  /// HCP only: the c-axis (stacking direction) along the load; else the load
  /// lies in the close-packed planes.
  bool load_along_c_axis = false;
  double length = 25.0;        ///< L in d0 (thesis: 25 for HCP, 100 amorphous)
  double width = 3.0;          ///< W in d0
  double wall_thickness = 1.5; ///< in d0
  double load = 0.01;          ///< compressive stress for the elastic test, in units of E
  double time_step = 0.1;      ///< in Δt_c
  double elastic_damping = 0.2;   ///< global damping for the elastic test, in c_c
  double strength_damping = 0.01; ///< global damping for the strength tests, in c_c
  double strain_rate = 1e-5;   ///< strength tests: ε̇ Δt
  double max_strain = 0.0;     ///< strength tests stop here (0: 3 σ_m,N/E)
  long max_elastic_steps = 40000;
  bool strengths = true;       ///< also run the tensile and shear tests
  unsigned seed = 1;           ///< amorphous sample
  /// The engine that integrates the tests (engine.hpp: "wearscale", "lammps").
  std::string engine = "wearscale";
};

struct PatchTestResult {
  std::size_t particles = 0;
  double d_min = 0.0, d_c = 0.0;  ///< (6.62), (6.35)
  // Elastic test.
  double c11 = 0.0, c12 = 0.0;    ///< confined modulus σ_yy/ε_yy and σ_xx/ε_yy
  double young = 0.0, poisson = 0.0;
  long elastic_steps = 0;
  bool elastic_converged = false;
  // Strength tests (peak stresses); targets follow (6.63) above d_c.
  std::optional<double> tensile_strength, shear_strength;
  double target_tensile = 0.0, target_shear = 0.0;
  long strength_steps = 0;
};

/// E and ν of an isotropic solid from its confined-compression moduli:
/// ν = C12/(C11 + C12), E = C11 (1 + ν)(1 − 2ν)/(1 − ν). NumericalError
/// (naming `step`) unless E > 0 and −1 < ν < 0.5: no elastic solid has
/// others, so such constants are a failed measurement, never a result.
struct IsotropicConstants {
  double young = 0.0, poisson = 0.0;
};
IsotropicConstants isotropic_constants(double c11, double c12, long step);

/// The particle size of a patch test that gives none: 0.6 d_c (6.35), the
/// smallest size of the thesis' lattices (§6.2.1).
double patch_test_d0(const CohesiveMaterial& m);

/// Observer of long runs: (phase, step, steps planned).
using PatchTestProgress = std::function<void(const std::string&, long, long)>;

/// `checkpoints` offers the state after every chunk of steps (the step it
/// gives counts the steps of all three tests) and resumes from one.
PatchTestResult run_patch_test(const PatchTestSpec& spec, const PatchTestProgress& progress = {},
                               const RunCheckpoints& checkpoints = {});

}  // namespace wearscale::dem
