#pragma once
// The figures of the headline curves (pin-on-disc friction and wear, disc
// profiles, friction and specific wear rate against the oxide thickness, DEM
// junctions), each a Figure (figure.hpp: PNG and PDF, its gnuplot script kept
// beside it), and the words their titles and legends name parameters with.
#include <filesystem>
#include <string>
#include <vector>

#include "wearscale/coupling/figure.hpp"
#include "wearscale/io/config.hpp"

namespace wearscale::coupling {

/// A length as a reader writes it: "0.5 µm", "3 mm", "120 nm", "0", "∞".
std::string length_words(double metres);

/// A swept key's value in words, for a legend or a title: for the oxide,
/// ("materials.layer.thickness", "5e-07") → "SiO2 layer 0.5 µm", "0" → "no
/// SiO2 layer", "inf" → "bulk SiO2" (the layer's material from `c`); for the
/// pin-on-disc keys a word and a unit ("load 2 N", "speed 8 mm/s", "disc
/// tilt 0.02"); any other key as "<last part, '_' as ' '> <value>".
std::string parameter_words(const Config& c, const std::string& key, const std::string& value);

/// What a pin-on-disc case is, in words, of what `c` sets: "SiO2 pin on Si
/// disc, SiO2 layer 1 µm, pin radius 3 mm, load 1 N, speed 8 mm/s"; the keys
/// in `left_out` (a sweep's) are left out.
std::string pin_on_disc_parameters(const Config& c, const std::vector<std::string>& left_out = {});

/// The title of a run's figures: the case's name (its first 150 characters),
/// then its parameters in words (two lines).
std::string run_title(const Config& c, const std::string& case_name);

/// The title of a sweep's figures: the case's name (150 characters at most), then its parameters but
/// the swept ones, then what is swept, in words: "swept: SiO2 layer thickness".
std::string sweep_title(const Config& c, const std::string& case_name, const std::string& key,
                        const std::string& series_key = "");

/// One run's curves: its legend entry and its table (friction.csv, disc_profile.csv).
struct FrictionCurve {
  std::string label;
  std::filesystem::path csv;
};

/// μ(s) (raw faint, its moving average full, Fig. 9.23) and the worn volumes
/// V(s) of pin (dashed, with markers: visible on the disc's line when they
/// are equal) and disc, in mm³ (µm³ below 10⁻³ mm³), of one or several runs
/// (`curves`, tables inside `folder`); one run's legend gives its specific
/// wear rates k in mm³/(N·m).
Figure friction_figure(const std::string& name, const std::string& title, const std::vector<FrictionCurve>& curves,
                       const std::filesystem::path& folder);

/// The final disc surface across the track (disc_profile.csv of each run:
/// x in mm, 0 on the pin's axis; depth in µm), with the oxide/substrate
/// interface at −`layer_thickness` when it is one finite thickness (> 0).
Figure disc_profiles_figure(const std::string& name, const std::string& title,
                            const std::vector<FrictionCurve>& profiles, double layer_thickness,
                            const std::filesystem::path& folder);

/// A sweep table (one per series of a sweep) and the name of its curve.
struct SweepTable {
  std::string label;
  std::filesystem::path csv;
};

/// Fig. 9.25 and the wear behind it: final (and mean) μ against the oxide
/// thickness (µm), bulk (inf) as its own marker at 6 µm as the thesis places
/// it, with the experimental fit μ ≈ 0.337 + 0.070 h_layer[µm] (9.1) over
/// 0–3 µm; below, the specific wear rates k of pin and disc in mm³/(N·m).
Figure friction_vs_thickness_figure(const std::string& name, const std::string& title,
                                    const std::vector<SweepTable>& tables, const std::filesystem::path& folder);

/// The force history of a sheared DEM junction (<history>_history.csv of
/// `wearscale dem junction`): F_T and F_N against the sliding distance.
Figure junction_force_figure(const std::string& name, const std::string& title, const std::filesystem::path& history_csv,
                             const std::filesystem::path& folder);

/// Peak p_T against p_N of the junction runs of nano/dem (junction_<pair>.csv),
/// a colour per D/L and a marker per outcome (sheared, flattened, detached),
/// with the fitted model p_T = max((D/L) σ, (p_N/p_crit) σ) of (7.9)-(7.10)
/// and p_T = p_N (Fig. 7.2, 7.3). With the cell `length` L [m] the legend
/// gives D in nm.
Figure junction_strength_figure(const std::string& name, const std::string& title,
                                const std::filesystem::path& runs_csv, const std::vector<double>& contact_ratios,
                                double sigma, double p_crit, double length, const std::filesystem::path& folder);

}  // namespace wearscale::coupling
