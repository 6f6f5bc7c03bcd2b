#include "backends/pin_on_disc_surfaces.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "wearscale/bem/roughness.hpp"
#include "wearscale/bem/spectral_modes.hpp"
#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/bem/topography.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/units.hpp"
#include "wearscale/io/topography_io.hpp"

namespace wearscale::coupling {

namespace {

using Weights = std::vector<std::vector<std::pair<std::size_t, double>>>;

// Target cell t covers [t·D, (t+1)·D); source sample a stands for [a·d, (a+1)·d).
// The weight of a in t is their overlap over D (the weights of a cell sum to 1).
Weights overlap_weights(std::size_t targets, double D, std::size_t sources, double d) {
  Weights w(targets);
  for (std::size_t t = 0; t < targets; ++t) {
    const double lo = static_cast<double>(t) * D, hi = lo + D;
    const auto first = static_cast<std::size_t>(std::max(0.0, std::floor(lo / d)));
    for (std::size_t a = first; a < sources; ++a) {
      const double a_lo = static_cast<double>(a) * d;
      if (a_lo >= hi) break;
      const double overlap = std::min(hi, a_lo + d) - std::max(lo, a_lo);
      if (overlap > 0.0) w[t].emplace_back(a, overlap / D);
    }
    double sum = 0.0;
    for (auto& [a, v] : w[t]) sum += v;
    for (auto& [a, v] : w[t]) v /= sum;  // the last sample may end short of the cell by rounding
  }
  return w;
}

std::string what_target(const std::string& key) { return key == "pin_surface" ? "pin's window" : "disc's track"; }

InitialSurface from_file(const Config& c, const std::string& key, const Config& table, const std::string& file_key,
                         const bem::TopographyOptions& options, const std::string& level, const Grid2D& g) {
  const auto file = table.path(file_key);
  bem::MeasuredTopography m;
  try {
    m = bem::read_measured_topography(file, options);
  } catch (const InputError& e) {
    throw table.error(file_key, e.what(), "a topography file wearscale reads: " + bem::supported_topography_formats());
  }
  const Grid2D& f = m.heights.grid();
  constexpr double slack = 1e-9;
  if (f.lx < g.lx * (1.0 - slack) || f.ly < g.ly * (1.0 - slack))
    throw table.error(file_key,
                      fmt::format("{} ({}) is {:g} m × {:g} m, smaller than the {} of {:g} m × {:g} m it must cover",
                                  file.string(), m.format, f.lx, f.ly, what_target(key), g.lx, g.ly),
                      fmt::format("a surface of at least {:g} m × {:g} m (size{})", g.lx, g.ly,
                                  key == "pin_surface" ? " × size" : " × the track's length, path_length"));
  if (f.dx() > g.dx() * (1.0 + slack) || f.dy() > g.dy() * (1.0 + slack))
    throw table.error(file_key,
                      fmt::format("{} ({}) is sampled every {:g} m × {:g} m ({} × {} points), coarser than the "
                                  "model's {:g} m cells",
                                  file.string(), m.format, f.dx(), f.dy(), f.nx, f.ny, g.dx()),
                      fmt::format("a sampling step of at most size/grid = {:g} m along x and y (a finer grid of "
                                  "the file, or a coarser scale.macro.grid)",
                                  g.dx()));
  RealField h(g);
  const bool same = std::abs(f.dx() - g.dx()) <= 1e-12 * g.dx() && std::abs(f.dy() - g.dy()) <= 1e-12 * g.dy();
  if (same) {
    for (std::size_t i = 0; i < g.nx; ++i)
      for (std::size_t j = 0; j < g.ny; ++j) h(i, j) = m.heights(i, j);
  } else {
    const Weights wx = overlap_weights(g.nx, g.dx(), f.nx, f.dx()), wy = overlap_weights(g.ny, g.dy(), f.ny, f.dy());
    for (std::size_t i = 0; i < g.nx; ++i)
      for (std::size_t j = 0; j < g.ny; ++j) {
        double sum = 0.0;
        for (const auto& [a, u] : wx[i])
          for (const auto& [b, v] : wy[j]) sum += u * v * m.heights(a, b);
        h(i, j) = sum;
      }
  }
  if (level == "plane") {
    bem::remove_plane(h);
  } else {
    const double mean = bem::mean_height(h);
    for (double& v : h) v -= mean;
  }
  (void)c;
  return {{h.begin(), h.end()},
          fmt::format("{} ({}, {} × {} points over {:g} m × {:g} m), {} onto {} × {} cells of {:g} m, {} removed",
                      file.string(), m.format, f.nx, f.ny, f.lx, f.ly, same ? "copied" : "area-averaged", g.nx, g.ny,
                      g.dx(), level == "plane" ? "least-squares plane" : "mean")};
}

InitialSurface generated(const Config& t, const Grid2D& g, double window) {
  bem::RoughSurfaceSpec spec;
  spec.grid = g;
  spec.hurst = t.number("hurst", Range::open_closed(0.0, 1.0));
  // k in units of the window (k = L/λ: `surface generate --size L --kl k`), or wavelengths.
  const double n_half = 0.5 * window / g.dx();  // the window's Nyquist wavenumber
  double kl = 0.0, kr = 0.0, ks = 0.0;
  const bool by_k = t.has("k_l") || t.has("k_s") || t.has("k_r");
  if (by_k) {
    kl = t.number("k_l", Range::closed(1.0, n_half));
    kr = t.number_or("k_r", kl, Range::closed(kl, n_half));
    ks = t.number("k_s", Range::closed(kr, n_half));
  } else {
    const double shortest = 2.0 * g.dx();
    const double ll = t.number("lambda_l", Range::closed(shortest, window), units::length);
    const double lr = t.number_or("lambda_r", ll, Range::closed(shortest, ll), units::length);
    const double ls = t.number("lambda_s", Range::closed(shortest, lr), units::length);
    kl = window / ll;
    kr = window / lr;
    ks = window / ls;
  }
  // On the target: k on its reference length (the longer side); the same wavelengths.
  const double scale = bem::reference_length(g) / window;
  spec.k_l = scale == 1.0 ? kl : kl * scale;
  spec.k_r = scale == 1.0 ? kr : kr * scale;
  spec.k_s = scale == 1.0 ? ks : std::min(ks * scale, bem::nyquist_wavenumber(g));
  spec.seed = static_cast<std::uint64_t>(t.integer_or("seed", 0, Range::non_negative()));
  const int targets = int(t.has("hprime_rms")) + int(t.has("h_rms")) + int(t.has("sa"));
  if (targets != 1) throw t.error("hprime_rms", "give exactly one of hprime_rms, h_rms, sa", "one roughness target");
  const char* key = t.has("hprime_rms") ? "hprime_rms" : t.has("h_rms") ? "h_rms" : "sa";
  bem::RoughnessMeasure measure = bem::RoughnessMeasure::HPrimeRms;
  double target = 0.0;
  if (t.has("hprime_rms")) {
    target = t.number("hprime_rms", Range::open_closed(0.0, bem::max_hprime_rms));
  } else if (t.has("h_rms")) {
    measure = bem::RoughnessMeasure::HRms;
    target = t.number("h_rms", Range::positive(), units::length);
  } else {
    measure = bem::RoughnessMeasure::Sa;
    target = t.number("sa", Range::positive(), units::length);
  }
  if (const auto p = bem::roughness_target_problem(spec, measure, target); !p.problem.empty())
    throw t.error(key, p.problem, p.allowed);
  RealField h = bem::generate_surface(spec, measure, target);
  const double mean = bem::mean_height(h);
  for (double& v : h) v -= mean;
  return {{h.begin(), h.end()},
          fmt::format("generated: H = {:g}, k = {:g}…{:g} (roll-off {:g}) of the {:g} m window, {} = {:g}, seed {}, "
                      "on {} × {} cells of {:g} m",
                      spec.hurst, kl, ks, kr, window, bem::name(measure), target, spec.seed, g.nx, g.ny, g.dx())};
}

}  // namespace

InitialSurface read_initial_surface(const Config& c, const std::string& key, const Grid2D& g, double window) {
  if (c.keys(key).empty()) return from_file(c, key, c, key, {}, "plane", g);
  const Config t = c.section(key);
  if (t.has("file")) {
    bem::TopographyOptions options;
    options.dataset = t.string_or("dataset", bem::default_surface_dataset);
    options.missing = bem::missing_points_from(
        t.choice_or(bem::MissingPointsChoice::key, bem::MissingPointsChoice::fallback, {"refuse", "fill"}),
        t.full_key(bem::MissingPointsChoice::key));
    const std::string level = t.choice_or("level", "plane", {"plane", "mean"});
    return from_file(c, key, t, "file", options, level, g);
  }
  return generated(t, g, window);
}

}  // namespace wearscale::coupling
