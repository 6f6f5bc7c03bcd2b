// wearscale surface generate --n N --size L --hurst H --kl K --ks K (--hprime-rms X | --h-rms X | --sa X) --out FILE.h5
// wearscale surface analyze FILE [--dataset D] [--size L] [--qmin Q --qmax Q] [--no-window] [--psd-out FILE.csv] [--json]
//
// Rough surfaces of thesis §1.1.2 (Fig. 1.3) and the topography analysis of §8.1.1.
#include <charconv>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "wearscale/bem/roughness.hpp"
#include "wearscale/bem/spectral_modes.hpp"
#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/bem/topography.hpp"
#include "wearscale/bem/topography_io.hpp"
#include "wearscale/core/csv.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/core/output_lock.hpp"
#include "wearscale/core/units.hpp"

namespace wearscale::app {

namespace {

namespace fs = std::filesystem;

/// A length from "1e-4" (metres) or "100 um".
double parse_length(const std::string& option, const std::string& text) {
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  bool ok = ec == std::errc() && ptr == text.data() + text.size();
  if (!ok) {
    try {
      const auto q = units::parse_quantity(text);
      ok = q.dimension == units::length;
      v = q.value;
    } catch (const std::exception&) {
      ok = false;
    }
  }
  if (!ok || !std::isfinite(v) || v <= 0.0)
    throw InputError(fmt::format("{} = '{}' is not a length; allowed: a positive length in metres (1e-4) or with a "
                                 "unit (\"100 um\")", option, text));
  return v;
}

/// --size L or --size LX,LY: the sides, or nothing if the option was not given.
bem::TopographySize parse_size(const std::string& text) {
  std::vector<std::string> values;
  for (std::size_t start = 0; !text.empty();) {
    const std::size_t comma = text.find(',', start);
    values.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (values.size() > 2)
    throw InputError(fmt::format("--size = '{}' has {} values; allowed: L or Lx,Ly", text, values.size()));
  bem::TopographySize size;
  if (!values.empty()) size.lx = parse_length("--size", values[0]);
  if (values.size() > 1) size.ly = parse_length("--size", values[1]);
  return size;
}

/// The library names its parameters (k_s, hurst, …); say which option sets each.
[[noreturn]] void rethrow_with_options(const InputError& e) {
  static const std::pair<const char*, const char*> options[] = {
      {"'hurst'", "--hurst"}, {"'k_l'", "--kl"}, {"'k_r'", "--kr"}, {"'k_s'", "--ks"},
      {"'grid'", "--n/--nx/--ny"}, {"'lx'", "--size"}, {"'ly'", "--size"}};
  std::string message = e.what();
  for (const auto& [key, option] : options)
    if (message.find(key) != std::string::npos) {
      message += fmt::format(" (option {})", option);
      break;
    }
  throw InputError(message);
}

nlohmann::json grid_json(const Grid2D& g) { return {{"nx", g.nx}, {"ny", g.ny}, {"lx", g.lx}, {"ly", g.ly}}; }

// ------------------------------------------------------------- generate ---

struct GenerateOptions {
  long n = 0, nx = 0, ny = 0;
  std::string size;
  double hurst = 0.0, k_l = 0.0, k_r = std::numeric_limits<double>::quiet_NaN(), k_s = 0.0;
  std::uint64_t seed = 0;
  double hprime_rms = 0.0, h_rms = 0.0, sa = 0.0;
  CLI::Option *hprime_opt = nullptr, *hrms_opt = nullptr, *sa_opt = nullptr, *kr_opt = nullptr;
  std::string out;
  bool json = false;
};

int run_generate(const GenerateOptions& o) {
  if (o.n == 0 && (o.nx == 0 || o.ny == 0))
    throw InputError("surface generate: the grid is not given; give --n N (square) or --nx and --ny");
  const auto nx = static_cast<std::size_t>(o.nx != 0 ? o.nx : o.n);
  const auto ny = static_cast<std::size_t>(o.ny != 0 ? o.ny : o.n);
  const auto size = parse_size(o.size);
  const double lx = *size.lx, ly = size.ly.value_or(lx);

  const int targets = static_cast<int>(o.hprime_opt->count() > 0) + static_cast<int>(o.hrms_opt->count() > 0) +
                      static_cast<int>(o.sa_opt->count() > 0);
  if (targets != 1)
    throw InputError(fmt::format("surface generate: give exactly one of --hprime-rms, --h-rms, --sa (got {})", targets));
  const auto [measure, target] = o.hprime_opt->count() > 0 ? std::pair{bem::RoughnessMeasure::HPrimeRms, o.hprime_rms}
                                 : o.hrms_opt->count() > 0 ? std::pair{bem::RoughnessMeasure::HRms, o.h_rms}
                                                           : std::pair{bem::RoughnessMeasure::Sa, o.sa};
  // Bounds that keep every derived figure finite and the surface a surface:
  // an RMS slope up to 100 (the BEM assumes small slopes: ≲ 1), heights up
  // to the side of the surface.
  const char* option = measure == bem::RoughnessMeasure::HPrimeRms ? "--hprime-rms"
                       : measure == bem::RoughnessMeasure::HRms    ? "--h-rms"
                                                                   : "--sa";
  const double most = measure == bem::RoughnessMeasure::HPrimeRms ? 100.0 : std::min(lx, ly);
  if (!std::isfinite(target) || target <= 0.0 || target > most)
    throw InputError(fmt::format("surface generate: {} = {:g}; allowed: > 0 and ≤ {:g}{}", option, target, most,
                                 measure == bem::RoughnessMeasure::HPrimeRms ? "" : " m (the side of the surface)"));
  // The surface, its spectrum and the copy written out, before any is allocated.
  require_memory(48.0 * static_cast<double>(nx) * static_cast<double>(ny),
                 fmt::format("surface generate: a {} × {} surface", nx, ny), "give a smaller --n (or --nx, --ny)");

  const bem::RoughSurfaceSpec spec{Grid2D(nx, ny, lx, ly), o.hurst, o.k_l, o.kr_opt->count() > 0 ? o.k_r : o.k_l,
                                   o.k_s, o.seed};
  RealField h;
  try {
    h = bem::generate_surface(spec, measure, target);
  } catch (const InputError& e) {
    rethrow_with_options(e);
  }

  const double sa = bem::sa(h), h_rms = bem::h_rms(h), h_prime = bem::h_prime_rms(h);
  for (const auto& [name, v] : {std::pair{"Sa", sa}, std::pair{"h_rms", h_rms}, std::pair{"h'_rms", h_prime}})
    if (!std::isfinite(v) || !(v > 0.0))
      throw NumericalError("surface generate", 0, name, fmt::format("{} of the generated surface", v));
  const fs::path out(o.out);
  const OutputLock lock = OutputLock::file(out, invocation());  // two generations into one file: one at a time
  const fs::path sidecar = bem::write_surface(out, h, bem::generation_attributes(spec));

  if (o.json) {
    const nlohmann::json j = {{"file", out.string()},
                              {"xdmf", sidecar.string()},
                              {"grid", grid_json(spec.grid)},
                              {"hurst", spec.hurst},
                              {"k_l", spec.k_l},
                              {"k_r", spec.k_r},
                              {"k_s", spec.k_s},
                              {"seed", spec.seed},
                              {"rescaled_to", {{"measure", bem::name(measure)}, {"value", target}}},
                              {"Sa", sa},
                              {"h_rms", h_rms},
                              {"h_prime_rms", h_prime}};
    std::cout << j.dump(2) << '\n';
  } else {
    std::cout << fmt::format("{:<12} {:>14.6g} m\n", "Sa", sa);
    std::cout << fmt::format("{:<12} {:>14.6g} m\n", "h_rms", h_rms);
    std::cout << fmt::format("{:<12} {:>14.6g}   (spectral)\n", "h'_rms", h_prime);
  }
  log::info("wrote {} and {}", out.string(), sidecar.string());
  return 0;
}

// -------------------------------------------------------------- analyze ---

struct AnalyzeOptions {
  std::string file, dataset = bem::default_surface_dataset;
  std::string size, missing = bem::MissingPointsChoice::fallback;
  double q_min = 0.0, q_max = 0.0;
  CLI::Option *qmin_opt = nullptr, *qmax_opt = nullptr;
  bool window = true;
  std::string psd_out;
  bool json = false;
};

int run_analyze(const AnalyzeOptions& o) {
  bem::TopographyOptions read;
  read.dataset = o.dataset;
  read.size = parse_size(o.size);
  read.missing = bem::missing_points_from(o.missing, "--missing");
  const bem::MeasuredTopography measured = bem::read_measured_topography(o.file, read);
  RealField h = measured.heights;
  const Grid2D& g = h.grid();
  // Analysed on the memory of a few copies of the grid (window, PSD, spectrum).
  require_memory(64.0 * static_cast<double>(g.size()), fmt::format("surface analyze: a {} × {} topography", g.nx, g.ny));
  double largest = 0.0;
  for (const double v : h) largest = std::max(largest, std::abs(v));
  bem::PlaneFit plane;
  double h_prime = 0.0;
  RealField psd;
  if (o.window) {
    // Measured, non-periodic data (§8.1.1): level, slopes by finite differences,
    // radial Hann window before the DFT.
    plane = bem::remove_plane(h);
    h_prime = bem::h_prime_rms_finite_difference(h);
    psd = bem::psd_2d(bem::windowed(h, bem::radial_hann_window(g)));
  } else {
    // Periodic data (a generated surface): as it is, slopes spectrally.
    h_prime = bem::h_prime_rms(h);
    psd = bem::psd_2d(h);
  }
  const double sa = bem::sa(h), h_rms = bem::h_rms(h);
  // A flat topography (constant, or a plane) leaves rounding noise, whose
  // PSD fits any exponent: there is no roughness to analyse.
  if (!(h_rms > 1e-10 * largest))
    throw InputError(fmt::format("{}: the topography is flat: h_RMS = {:g} m {}, rounding noise of heights up to {:g} "
                                 "m; allowed: a rough surface",
                                 o.file, h_rms, o.window ? "once levelled" : "about its mean", largest));
  const bem::RadialPsd radial = bem::radial_psd(psd);
  if (radial.q.size() < 3)
    throw InputError(fmt::format("{}: a {} × {} topography gives {} radial PSD bin(s); at least 3 are needed for a "
                                 "Hurst fit", o.file, g.nx, g.ny, radial.q.size()));
  // Default band: the self-affine band k_r … k_s of a surface that records it
  // (written by `surface generate`), else everything above the first 2 bins.
  const auto k_r = bem::read_surface_attribute(o.file, o.dataset, "k_r");
  const auto k_s = bem::read_surface_attribute(o.file, o.dataset, "k_s");
  const bool recorded = k_r && k_s;
  const double unit = bem::wavenumber_unit(g);
  const double q_min = o.qmin_opt->count() > 0 ? o.q_min : recorded ? *k_r * unit : radial.q[2];
  const double q_max = o.qmax_opt->count() > 0 ? o.q_max : recorded ? *k_s * unit : radial.q.back();
  const bem::HurstFit fit = bem::fit_hurst(radial, q_min, q_max);
  // A self-affine surface has 0 < H ≤ 1: anything else says the band is not
  // self-affine (a roll-off plateau, or beyond the shortest wavelength).
  if (!(fit.hurst > 0.0 && fit.hurst <= 1.0 + 3.0 * fit.hurst_error) || !std::isfinite(fit.hurst_error))
    throw NumericalError("surface analyze", 0, "Hurst exponent",
                         fmt::format("the PSD over q = {:.4g} … {:.4g} rad/m{} fits H = {:.3f} ± {:.3f}, outside (0, 1]: "
                                     "that band is not self-affine; give the self-affine band with --qmin and --qmax",
                                     fit.q_min, fit.q_max, recorded ? "" : " (the default band: the file records no k_r, k_s)",
                                     fit.hurst, fit.hurst_error));

  if (!o.psd_out.empty()) {
    std::vector<double> count(radial.count.begin(), radial.count.end());
    const fs::path csv(o.psd_out);
    write_csv(csv, {"q", "C", "count"}, {radial.q, radial.c, count}, {"rad/m", "m^4", "1"},
              {fmt::format("radial PSD of {} ({}), C = LxLy/(nx²ny²)|ĥ|² (thesis 1.9)", o.file, g.to_string()),
               o.window ? "plane removed, radial Hann window, normalised by <w²>" : "no window (periodic data)",
               "q_rad_per_m: mean |q| of the bin; C_m4: mean PSD; count: modes in the bin"});
  }

  const char* method = o.window ? "finite-difference" : "spectral";
  if (o.json) {
    nlohmann::json j = {{"file", o.file},
                        {"format", measured.format},
                        {"missing_points", measured.missing},
                        {"missing", bem::name(read.missing)},
                        {"grid", grid_json(g)},
                        {"window", o.window},
                        {"Sa", sa},
                        {"h_rms", h_rms},
                        {"h_prime_rms", h_prime},
                        {"h_prime_rms_method", method},
                        {"hurst", fit.hurst},
                        {"hurst_error", fit.hurst_error},
                        {"fit",
                         {{"q_min", fit.q_min}, {"q_max", fit.q_max}, {"points", fit.points}, {"slope", fit.slope},
                          {"slope_error", fit.slope_error}}}};
    if (o.window) j["plane"] = {{"offset", plane.offset}, {"slope_x", plane.slope_x}, {"slope_y", plane.slope_y}};
    j["psd_csv"] = o.psd_out.empty() ? nlohmann::json(nullptr) : nlohmann::json(o.psd_out);
    std::cout << j.dump(2) << '\n';
  } else {
    std::cout << fmt::format("{:<12} {} ({} × {} points, {:.6g} × {:.6g} m{})\n", "read", measured.format, g.nx, g.ny,
                             g.lx, g.ly,
                             measured.missing == 0 ? "" : fmt::format(", {} missing points filled", measured.missing));
    std::cout << fmt::format("{:<12} {:>14.6g} m\n", "Sa", sa);
    std::cout << fmt::format("{:<12} {:>14.6g} m\n", "h_rms", h_rms);
    std::cout << fmt::format("{:<12} {:>14.6g}   ({})\n", "h'_rms", h_prime, method);
    std::cout << fmt::format("{:<12} {:>14.4f} ± {:.4f}   (fit on {} bins, q = {:.4g} … {:.4g} rad/m)\n", "H",
                             fit.hurst, fit.hurst_error, fit.points, fit.q_min, fit.q_max);
  }
  if (!o.psd_out.empty()) log::info("wrote {}", o.psd_out);
  return 0;
}

}  // namespace

Command add_surface(CLI::App& app) {
  auto* cmd = app.add_subcommand("surface", "Rough surfaces: generate one from a PSD, analyze a topography "
                                            "(Sa, h_RMS, h'_RMS, radial PSD, Hurst exponent)");
  cmd->require_subcommand(1);

  auto g = std::make_shared<GenerateOptions>();
  auto* gen = cmd->add_subcommand("generate", "Generate a periodic rough surface with the PSD of thesis Fig. 1.3 "
                                              "(plateau k_l…k_r, slope −2(H+1) from k_r to k_s) and write it to HDF5 + XDMF");
  gen->add_option("--n", g->n, "Points per side of a square grid")->check(CLI::Range(4L, 1L << 16));
  gen->add_option("--nx", g->nx, "Points along x (overrides --n)")->check(CLI::Range(4L, 1L << 16));
  gen->add_option("--ny", g->ny, "Points along y (overrides --n)")->check(CLI::Range(4L, 1L << 16));
  gen->add_option("--size", g->size, "Side L of the square surface [m] (\"100 um\" also works), or Lx,Ly")
      ->required();
  gen->add_option("--hurst", g->hurst, "Hurst exponent H in (0, 1]")->required();
  gen->add_option("--kl", g->k_l, "Wavenumber of the longest wavelength, q_l = 2π k_l / L")->required();
  g->kr_opt = gen->add_option("--kr", g->k_r, "Roll-off wavenumber k_r (default: k_l, no plateau)");
  gen->add_option("--ks", g->k_s, "Wavenumber of the shortest wavelength, at most min(nx, ny)/2")->required();
  gen->add_option("--seed", g->seed, "Seed of the random phases (same seed, same surface)")->capture_default_str();
  g->hprime_opt = gen->add_option("--hprime-rms", g->hprime_rms, "Rescale to this RMS slope h'_RMS (1.6)");
  g->hrms_opt = gen->add_option("--h-rms", g->h_rms, "Rescale to this RMS height h_RMS (1.5) [m]");
  g->sa_opt = gen->add_option("--sa", g->sa, "Rescale to this arithmetic mean deviation Sa (1.4) [m]");
  g->hprime_opt->excludes(g->hrms_opt)->excludes(g->sa_opt);
  g->hrms_opt->excludes(g->sa_opt);
  gen->add_option("--out", g->out, "Output HDF5 file (dataset /surface/height); an .xdmf sidecar is written beside it")
      ->required();
  gen->add_flag("--json", g->json, "Print the achieved roughness and the parameters as one JSON object");

  auto a = std::make_shared<AnalyzeOptions>();
  auto* ana = cmd->add_subcommand("analyze", "Roughness, radial PSD and Hurst exponent of a topography (measured: "
                                             "X3P, Gwyddion, Digital Surf, SDF, Zygo; or HDF5, text grid)");
  ana->add_option("file", a->file, "Topography: " + bem::supported_topography_formats() +
                                       "; text grids have rows along x, columns along y (see docs/topography.md)")
      ->required();
  ana->add_option("--missing", a->missing, bem::MissingPointsChoice::doc)->capture_default_str();
  ana->add_option("--dataset", a->dataset, "HDF5 dataset holding the heights")->capture_default_str();
  ana->add_option("--size", a->size, "Side Lx [m] (\"877 um\" also works; Ly from square pixels), or Lx,Ly; "
                                     "overrides the file's sizes; needed for text files without '# lx = ...'");
  a->qmin_opt = ana->add_option("--qmin", a->q_min, "Lower end of the fit band [rad/m] (default: 2π k_r/L if the file records k_r, as generated surfaces do, else above the first 2 PSD bins)");
  a->qmax_opt = ana->add_option("--qmax", a->q_max, "Upper end of the fit band [rad/m] (default: 2π k_s/L if the file records k_s, else the last bin)");
  ana->add_flag("--window,!--no-window", a->window,
                "Level the data and apply a radial Hann window before the PSD (default, for measured data); "
                "--no-window for periodic surfaces such as generated ones");
  ana->add_option("--psd-out", a->psd_out, "Write the radial PSD as CSV (columns q_rad_per_m, C_m4, count)");
  ana->add_flag("--json", a->json, "Print the results as one JSON object");

  return [gen, g, a]() { return gen->parsed() ? run_generate(*g) : run_analyze(*a); };
}

}  // namespace wearscale::app
