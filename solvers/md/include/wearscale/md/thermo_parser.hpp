#pragma once
// The shear stress–strain curve of one LAMMPS shear test, read from the
// `fix ave/time` file the deck writes (shear.dat: one row per `sample_steps`
// steps, each the average over those steps of: strain, shear stress τ [GPa],
// normal stress p_N [GPa], sheared height h [Å], temperature [K]), and the two
// strengths taken from it: σ_max = the largest τ, σ_dyn = the mean τ over a
// strain window after failure.
//
// Chosen over the thermo table of log.lammps because its columns are fixed
// by the deck, it is flushed as it is written (progress), and its rows are
// averages rather than instantaneous values.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace wearscale::md {

/// One averaged row, in SI.
struct ShearSample {
  long step = 0;
  double strain = 0.0;         ///< top-wall displacement / sheared height
  double shear_stress = 0.0;   ///< τ resisting sliding [Pa]
  double normal_stress = 0.0;  ///< p_N measured on the top wall, compressive > 0 [Pa]
  double height = 0.0;         ///< distance between the wall centroids [m]
  double temperature = 0.0;    ///< mobile atoms, without the x (streaming) component [K]
};

struct ShearCurve {
  std::vector<ShearSample> samples;
  std::string source;  ///< file it was read from (messages)
};

/// Parses a fix ave/time file ('#' comment lines, then rows "step strain tau
/// pN h T"). NumericalError naming the file and line for a row with a wrong
/// column count, a non-number, NaN or Inf, decreasing steps, or no row.
ShearCurve parse_shear_curve(std::string_view text, const std::string& source);
ShearCurve read_shear_curve(const std::filesystem::path& file);

struct ShearStrength {
  double sigma_max = 0.0;       ///< peak shear stress [Pa]
  double strain_at_max = 0.0;
  double sigma_dyn = 0.0;       ///< mean shear stress over the window [Pa]
  double sigma_dyn_std = 0.0;   ///< standard deviation of τ over the window [Pa] (stick-slip)
  double window_begin = 0.0, window_end = 0.0;
  std::size_t window_samples = 0;
  double normal_stress = 0.0;       ///< mean measured p_N over the window [Pa]
  double temperature_window = 0.0;  ///< mean temperature over the window [K] (shear heating)
  double temperature_max = 0.0;     ///< highest row temperature of the run [K]
  bool failed_before_window = true; ///< the peak lies before the window begins
};

/// The slope dτ/d(strain) of the curve's elastic start: least squares (with
/// an intercept) over the rows with strain in (0, max_strain]. NumericalError
/// if fewer than 3 rows lie there.
double initial_slope(const ShearCurve& curve, double max_strain);

/// σ_max and σ_dyn of a curve. NumericalError if the curve does not reach
/// the end of the window (run stopped early) or the window holds no row.
ShearStrength shear_strength(const ShearCurve& curve, double window_begin, double window_end);

}  // namespace wearscale::md
