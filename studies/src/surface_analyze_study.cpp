// The topography-analysis study ([surface.analyze], §8.1.1): roughness (Sa,
// h_RMS, h'_RMS), the radial PSD and the Hurst exponent fitted on it, of a
// measured (X3P, Gwyddion, Digital Surf, SDF, Zygo) or generated (HDF5, text
// grid) topography; the radial PSD in run.h5 (/psd) and, optionally, as a CSV
// table in the output folder. A Hurst fit that fails (a band that is not
// self-affine) is reported as failed, with why (summary.json hurst_fit), and
// the rest stands: the fit is optional to the user.
//
//   [surface.analyze]
//   file = "scan.x3p"
//   missing = "fill"     # what to do with missing points: "refuse" (default) | "fill"
//   window = false       # periodic data (a generated surface): no levelling, no window
//   q_min = 2.5e5        # the fit band [rad/m]; default: the k_r … k_s a generated surface records
//   psd = "psd.csv"
#include <cmath>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "surface_sides.hpp"
#include "wearscale/bem/roughness.hpp"
#include "wearscale/bem/spectral_modes.hpp"
#include "wearscale/bem/topography.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/io/csv.hpp"
#include "wearscale/io/topography_io.hpp"
#include "wearscale/io/key_table.hpp"
#include "wearscale/studies/study.hpp"

namespace wearscale::studies {

namespace {

// [surface.analyze]: the file and how to read it, the fit band, the window and the PSD's table.
struct SurfaceAnalyzeKeys {
  std::filesystem::path file;
  bem::TopographyOptions read;    // dataset, size (as the file's when not given), missing
  std::optional<double> q_min, q_max;  // the fit band (absent: from the file, else the PSD's bins)
  bool window = true;
  std::string psd;                // "" : no table
};

const KeyTable<SurfaceAnalyzeKeys>& surface_analyze_keys() {
  using K = SurfaceAnalyzeKeys;
  using bem::MissingPoints;
  static const auto table =
      KeyTable<K>()
          .path("file", &K::file,
                "topography: " + bem::supported_topography_formats() +
                    "; text grids have rows along x, columns along y (see docs/topography.md)")
          .flag("file")
          .choice("missing", [](K& k) -> MissingPoints& { return k.read.missing; },
                  std::vector<std::pair<std::string, MissingPoints>>{{"refuse", MissingPoints::Refuse},
                                                                     {"fill", MissingPoints::Fill}},
                  bem::MissingPointsChoice::doc)
          .flag("--missing")
          .string("dataset", [](K& k) -> std::string& { return k.read.dataset; }, "HDF5 dataset holding the heights")
          .flag("--dataset")
          .custom("size", "number", "> 0", "m",
                  "side Lx (\"877 um\" also works; Ly from square pixels), or Lx,Ly; needed for text files without "
                  "'# lx = ...'",
                  [](const Config& c, const std::string& key, K& k) { k.read.size = read_sides(c, key); })
          .fallback("the file's")
          .flag("--size")
          .optional_number("q_min", &K::q_min, Range::non_negative(), units::dimensionless,
                           "lower end of the fit band (default: the k_r a generated surface records)")
          .unit("rad/m")
          .fallback("2π k_r/L, else above the first 2 PSD bins")
          .flag("--qmin")
          .optional_number("q_max", &K::q_max, Range::non_negative(), units::dimensionless,
                           "upper end of the fit band (default: the k_s a generated surface records)")
          .unit("rad/m")
          .fallback("2π k_s/L, else the last bin")
          .flag("--qmax")
          .boolean("window", &K::window,
                   "level the data and apply a radial Hann window before the PSD (measured data); false for periodic "
                   "surfaces such as generated ones")
          .flag("--no-window", "false")
          .checked_string("psd", &K::psd, "a file name ending in .csv",
                          "write the radial PSD as this CSV table in the output folder (columns q_rad_per_m, C_m4, "
                          "count)",
                          [](const Config&, const std::string&, K&) {})  // checked once the topography is read
          .flag("--psd-out");
  return table;
}

class SurfaceAnalyze final : public Study {
 public:
  std::string name() const override { return "surface/analyze"; }
  std::string summary() const override {
    return "Roughness, radial PSD and Hurst exponent of a topography (measured: X3P, Gwyddion, Digital Surf, SDF, "
           "Zygo; or HDF5, text grid)";
  }
  std::string default_case_name() const override { return "surface-analyze"; }
  Schema schema() const override { return surface_analyze_keys().schema("surface.analyze"); }

  // Reads the topography and checks it has a roughness to analyse, before anything is written.
  std::vector<std::string> prepare(Config& cfg) override {
    SurfaceAnalyzeKeys keys;
    surface_analyze_keys().read(cfg.section("surface.analyze"), keys);
    cfg.reject_unknown_keys();
    file_ = keys.file;
    const bem::TopographyOptions& read = keys.read;
    dataset_ = read.dataset;
    window_ = keys.window;
    q_min_ = keys.q_min;
    q_max_ = keys.q_max;

    measured_ = bem::read_measured_topography(file_, read);
    missing_ = read.missing;
    const Grid2D& g = measured_.heights.grid();
    // Analysed on the memory of a few copies of the grid (window, PSD, spectrum).
    // ... and the radial PSD's |q| bins, which grow with the aspect ratio (24 bytes a bin).
    require_memory(64.0 * static_cast<double>(g.size()) + 24.0 * bem::radial_psd_bins(g),
                   fmt::format("surface analyze: a {} × {} topography of {:g} × {:g} m ({:.3g} radial PSD bins)", g.nx,
                               g.ny, g.lx, g.ly, bem::radial_psd_bins(g)),
                   "check the sizes (the PSD's bins grow with the aspect ratio lx/ly)");
    double largest = 0.0;
    for (const double v : measured_.heights) largest = std::max(largest, std::abs(v));
    h_ = measured_.heights;
    if (window_) {
      // Measured, non-periodic data (§8.1.1): level, slopes by finite differences, radial Hann window.
      plane_ = bem::remove_plane(h_);
      h_prime_ = bem::h_prime_rms_finite_difference(h_);
    } else {
      h_prime_ = bem::h_prime_rms(h_);  // periodic data: as it is, slopes spectrally
    }
    // A flat topography (constant, or a plane) leaves rounding noise, whose PSD fits any exponent.
    if (!(bem::h_rms(h_) > 1e-10 * largest))
      throw InputError(fmt::format("{}: the topography is flat: h_RMS = {:g} m {}, rounding noise of heights up to {:g} "
                                   "m; allowed: a rough surface",
                                   file_.string(), bem::h_rms(h_), window_ ? "once levelled" : "about its mean", largest));
    // The table's name, after the topography's refusals (output_file_name: what the key allows).
    const Config c = cfg.section("surface.analyze");
    if (c.has("psd")) psd_ = output_file_name(c, "psd", "", {".csv"});
    return {};
  }

  // The topography as read and its levelled copy.
  double prepared_bytes() const override { return 16.0 * static_cast<double>(h_.grid().size()); }

  void run(const Config& /*cfg*/, RunContext& context) override {
    const Grid2D& g = h_.grid();
    const RealField psd = window_ ? bem::psd_2d(bem::windowed(h_, bem::radial_hann_window(g))) : bem::psd_2d(h_);
    const double sa = bem::sa(h_), h_rms = bem::h_rms(h_);
    const bem::RadialPsd radial = bem::radial_psd(psd);
    // The Hurst fit is optional to the user: when it fails (a band that is not self-affine, too few
    // bins), the run says why, in summary.json and as a warning, and the rest of the analysis stands.
    std::optional<bem::HurstFit> fit;
    std::string failure;
    bool recorded = false;
    if (radial.q.size() < 3) {
      failure = fmt::format("a {} × {} topography gives {} radial PSD bin(s); at least 3 are needed for a Hurst fit",
                            g.nx, g.ny, radial.q.size());
    } else {
      // Default band: the self-affine band k_r … k_s of a surface that records it (written by `surface
      // generate`), else everything above the first 2 bins.
      const auto k_r = bem::read_surface_attribute(file_, dataset_, "k_r");
      const auto k_s = bem::read_surface_attribute(file_, dataset_, "k_s");
      recorded = k_r && k_s;
      const double unit = bem::wavenumber_unit(g);
      const double q_min = q_min_ ? *q_min_ : recorded ? *k_r * unit : radial.q[2];
      const double q_max = q_max_ ? *q_max_ : recorded ? *k_s * unit : radial.q.back();
      try {
        fit = bem::fit_hurst(radial, q_min, q_max);
      } catch (const InputError& e) {
        if (q_min_ || q_max_) throw;  // a band the user gave: bad input
        failure = e.what();
      }
      // A self-affine surface has 0 < H ≤ 1: anything else says the band is not self-affine.
      if (fit && (!(fit->hurst > 0.0 && fit->hurst <= 1.0 + 3.0 * fit->hurst_error) || !std::isfinite(fit->hurst_error)))
        failure = fmt::format("the PSD over q = {:.4g} … {:.4g} rad/m{} fits H = {:.3f} ± {:.3f}, outside (0, 1]: that "
                              "band is not self-affine; give the self-affine band with --qmin and --qmax (q_min, q_max)",
                              fit->q_min, fit->q_max, recorded ? "" : " (the default band: the file records no k_r, k_s)",
                              fit->hurst, fit->hurst_error);
    }
    if (!failure.empty()) log::warn("surface analyze {}: no Hurst exponent: {}", file_.string(), failure);
    {  // The radial PSD, always, in run.h5 (and as a CSV table when asked)
      std::vector<double> count(radial.count.begin(), radial.count.end());
      context.h5().write_table("/psd", {"q", "C", "count"}, {radial.q, radial.c, count}, {"rad/m", "m^4", "1"});
    }
    if (!psd_.empty()) {
      std::vector<double> count(radial.count.begin(), radial.count.end());
      const auto csv = context.output_dir() / psd_;
      write_csv(csv, {"q", "C", "count"}, {radial.q, radial.c, count}, {"rad/m", "m^4", "1"},
                {fmt::format("radial PSD of {} ({}), C = LxLy/(nx²ny²)|ĥ|² (thesis 1.9)", file_.string(), g.to_string()),
                 window_ ? "plane removed, radial Hann window, normalised by <w²>" : "no window (periodic data)",
                 "q_rad_per_m: mean |q| of the bin; C_m4: mean PSD; count: modes in the bin"});
      context.add_file(csv);
      context.note("psd_csv", csv.string());
    } else {
      context.note("psd_csv", nullptr);
    }
    context.report("Sa", sa, "m", "arithmetic mean deviation Sa (1.4)");
    context.report("h_rms", h_rms, "m", "RMS height h_RMS (1.5)");
    context.report("h_prime_rms", h_prime_, "1", window_ ? "RMS slope h'_RMS, finite differences" : "RMS slope h'_RMS (1.6), spectral");
    if (failure.empty()) {
      context.report("hurst", fit->hurst, "1", "Hurst exponent H fitted on the radial PSD");
      context.report("hurst_error", fit->hurst_error, "1", "standard error of H");
    }
    context.note("file", file_.string());
    context.note("format", measured_.format);
    context.note("missing_points", measured_.missing);
    context.note("missing", bem::name(missing_));
    context.note("grid", {{"nx", g.nx}, {"ny", g.ny}, {"lx", g.lx}, {"ly", g.ly}});
    context.note("window", window_);
    context.note("Sa", sa);
    context.note("h_rms", h_rms);
    context.note("h_prime_rms", h_prime_);
    context.note("h_prime_rms_method", window_ ? "finite-difference" : "spectral");
    context.note("hurst", failure.empty() ? nlohmann::json(fit->hurst) : nlohmann::json(nullptr));
    context.note("hurst_error", failure.empty() ? nlohmann::json(fit->hurst_error) : nlohmann::json(nullptr));
    context.note("hurst_fit", failure.empty() ? nlohmann::json{{"status", "done"}}
                                              : nlohmann::json{{"status", "failed"}, {"reason", failure}});
    if (fit)
      context.note("fit", {{"q_min", fit->q_min}, {"q_max", fit->q_max}, {"points", fit->points}, {"slope", fit->slope},
                           {"slope_error", fit->slope_error}, {"hurst", fit->hurst}, {"hurst_error", fit->hurst_error}});
    if (window_) context.note("plane", {{"offset", plane_.offset}, {"slope_x", plane_.slope_x}, {"slope_y", plane_.slope_y}});
  }

 private:
  std::filesystem::path file_;
  std::string dataset_, psd_;
  bool window_ = true;
  std::optional<double> q_min_, q_max_;
  bem::MeasuredTopography measured_;
  bem::MissingPoints missing_ = bem::MissingPoints::Refuse;
  RealField h_;
  bem::PlaneFit plane_;
  double h_prime_ = 0.0;
};

}  // namespace
}  // namespace wearscale::studies

WEARSCALE_STUDY(SurfaceAnalyze)
