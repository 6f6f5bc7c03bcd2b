#pragma once
// PNG plots of the headline curves with gnuplot, when it is installed
// (Debian: gnuplot-nox); otherwise a notice and no plot.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "wearscale/io/config.hpp"

namespace wearscale::coupling {

/// Whether `gnuplot` is on the PATH (checked once).
bool plotting_available();

/// Runs a gnuplot `script` (without terminal and output lines) that draws
/// `png`, written atomically: the PNG appears only if gnuplot succeeded
/// (a warning otherwise; nothing without gnuplot) and left a whole image
/// (OutputError if it did not: a full disk). Data files are read where they
/// are now (a staged output of the run, OutputSet::readable).
std::optional<std::filesystem::path> render_plot(const std::string& script, const std::filesystem::path& png,
                                                 int width = 1000, int height = 700);

/// A legend entry for a sweep's run folder name, "thickness=5e-07" → "h = 0.5 µm",
/// "thickness=0" → "h = 0 (no oxide)", "thickness=inf" → "h = ∞ (bulk oxide)", "slope=0.02 layer_test=disc" → "slope = 0.02, layer_test = disc".
std::string legend_label(const std::string& run_label);

/// The title of a sweep's figures, two lines: `case_name`, then what a reader
/// needs to place the curves, of those the case `c` sets: "SiO2 pin on Si disc,
/// R = 3 mm, F_N = 1 N, v = 8 mm/s; swept: materials.layer.thickness" (a swept
/// key's value is left to the legends; ", series: KEY" for a series key).
std::string sweep_title(const Config& c, const std::string& case_name, const std::string& key,
                        const std::string& series_key = "");

/// One curve set per run: label and its friction.csv (distance, friction, pin and disc wear).
struct FrictionCurve {
  std::string label;
  std::filesystem::path csv;
};

/// μ(s) and wear volumes V(s) of one or several runs, in one PNG (atomically
/// written): the raw μ faint and its moving average (the friction.csv column
/// friction_moving_average, Fig. 9.23) in full, when the file has it.
std::optional<std::filesystem::path> plot_friction_curves(const std::vector<FrictionCurve>& curves,
                                                          const std::filesystem::path& png, const std::string& title);

/// The final worn depth of the disc across the track (disc_profile.csv of each
/// run: x, depth, through_layer) of one or several runs, with the oxide's
/// thickness drawn when given (> 0): the grooves are where a curve passes it.
std::optional<std::filesystem::path> plot_disc_profiles(const std::vector<FrictionCurve>& profiles,
                                                        const std::filesystem::path& png, const std::string& title,
                                                        double layer_thickness);

/// A sweep table (one per series of a sweep) and the name of its curve.
struct SweepTable {
  std::string label;
  std::filesystem::path csv;
};

/// Fig. 9.25: final (and mean) μ against the oxide thickness (µm), one curve
/// per sweep table (e.g. planar and tilted discs), the finite thicknesses
/// joined and bulk (inf) as its own marker at 6 µm as the thesis places it,
/// with the experimental fit μ ≈ 0.337 + 0.070 h_layer[µm] (9.1) over the
/// thicknesses it was fitted on (0–3 µm).
std::optional<std::filesystem::path> plot_friction_vs_thickness(const std::vector<SweepTable>& tables,
                                                                const std::filesystem::path& png);

/// The tangential force history of a sheared DEM junction (junction_history.csv
/// of `wearscale dem junction`): F_T and F_N against the sliding distance.
std::optional<std::filesystem::path> plot_junction_force(const std::filesystem::path& history_csv,
                                                         const std::filesystem::path& png, const std::string& title);

/// Peak p_T against p_N of the junction runs of nano/dem (junction_<pair>.csv:
/// D/L, p_N, ..., p_T_peak, ..., outcome in columns 1, 2, 6, 9), a colour per
/// D/L and a marker per outcome (sheared, flattened, detached), with the fitted
/// model p_T = max((D/L) σ, (p_N/p_crit) σ) of (7.9)-(7.10): each D/L's plateau
/// (7.9) in its colour, the line (7.10) common to all once, and p_T = p_N
/// (Fig. 7.2, 7.3). `title` may be two lines ('\n'). With the cell `length` L
/// [m] the legend gives D in nm.
std::optional<std::filesystem::path> plot_junction_strength(const std::filesystem::path& runs_csv,
                                                            const std::filesystem::path& png, const std::string& title,
                                                            const std::vector<double>& contact_ratios, double sigma,
                                                            double p_crit, double length = 0.0);

}  // namespace wearscale::coupling
