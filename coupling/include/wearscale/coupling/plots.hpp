#pragma once
// PNG plots of the headline curves with gnuplot, when it is installed
// (Debian: gnuplot-nox); otherwise a notice and no plot.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

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

/// One curve set per run: label and its friction.csv (distance, friction, pin and disc wear).
struct FrictionCurve {
  std::string label;
  std::filesystem::path csv;
};

/// μ(s) and wear volumes V(s) of one or several runs, in one PNG (atomically written).
std::optional<std::filesystem::path> plot_friction_curves(const std::vector<FrictionCurve>& curves,
                                                          const std::filesystem::path& png, const std::string& title);

/// Time-averaged and final μ against the oxide thickness (µm) from a sweep
/// table, with the experimental fit μ ≈ 0.337 + 0.070 h_layer[µm] (9.1) and
/// bulk (inf) drawn at 6 µm as in Fig. 9.25.
std::optional<std::filesystem::path> plot_friction_vs_thickness(const std::filesystem::path& table_csv,
                                                                const std::filesystem::path& png);

/// The tangential force history of a sheared DEM junction (junction_history.csv
/// of `wearscale dem junction`): F_T and F_N against the sliding distance.
std::optional<std::filesystem::path> plot_junction_force(const std::filesystem::path& history_csv,
                                                         const std::filesystem::path& png, const std::string& title);

/// Peak p_T against p_N of the junction runs of nano/dem (junction_<pair>.csv:
/// D/L, p_N, ..., p_T_peak in columns 1, 2, 6), one point set per D/L, with the
/// fitted model p_T = max((D/L) σ, (p_N/p_crit) σ) of (7.9)-(7.10) per D/L
/// and the line p_T = p_N (Fig. 7.2, 7.3).
std::optional<std::filesystem::path> plot_junction_strength(const std::filesystem::path& runs_csv,
                                                            const std::filesystem::path& png, const std::string& title,
                                                            const std::vector<double>& contact_ratios, double sigma,
                                                            double p_crit);

}  // namespace wearscale::coupling
