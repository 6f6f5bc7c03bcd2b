// wearscale.surface: rough surfaces (§1.1.2), their roughness measures and
// spectra, and the topography files wearscale reads.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <optional>

#include "arrays.hpp"
#include "bindings.hpp"
#include "wearscale/bem/roughness.hpp"
#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/bem/topography.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/io/topography_io.hpp"

namespace wearscale::python {

namespace {

using namespace wearscale::bem;

py::dict generation_metadata(const RoughSurfaceSpec& spec) {
  py::dict meta;
  meta["lx_m"] = spec.grid.lx;
  meta["ly_m"] = spec.grid.ly;
  meta["hurst"] = spec.hurst;
  meta["k_l"] = spec.k_l;
  meta["k_r"] = spec.k_r;
  meta["k_s"] = spec.k_s;
  meta["seed"] = spec.seed;
  return meta;
}

py::tuple generate(std::size_t n, double size, double hurst, double k_l, std::optional<double> k_r, double k_s,
                   std::uint64_t seed, std::optional<std::size_t> ny, std::optional<double> ly,
                   std::optional<double> sa, std::optional<double> rms, std::optional<double> slope_rms) {
  RoughSurfaceSpec spec;
  spec.grid = Grid2D(n, ny.value_or(n), size, ly.value_or(size));
  spec.hurst = hurst;
  spec.k_l = k_l;
  spec.k_r = k_r.value_or(k_l);
  spec.k_s = k_s;
  spec.seed = seed;
  const int targets = int(sa.has_value()) + int(rms.has_value()) + int(slope_rms.has_value());
  if (targets > 1) throw InputError("surface.generate: give at most one of sa, rms, slope_rms");
  RealField h;
  {
    py::gil_scoped_release release;
    if (sa) h = generate_surface(spec, RoughnessMeasure::Sa, *sa);
    else if (rms) h = generate_surface(spec, RoughnessMeasure::HRms, *rms);
    else if (slope_rms) h = generate_surface(spec, RoughnessMeasure::HPrimeRms, *slope_rms);
    else h = generate_surface(spec);
  }
  return py::make_tuple(owned(std::move(h)), generation_metadata(spec));
}

py::dict analyze(const InArray& heights, double lx, double ly, double q_min, double q_max, bool detrend,
                 bool window) {
  const Grid2D g = grid_of(heights, lx, ly, "surface.analyze");
  RealField h = field_from(heights, g);
  py::dict out;
  RadialPsd radial;
  RealField psd;
  double sa_ = 0, rms = 0, slope = 0, slope_fd = 0;
  std::optional<HurstFit> fit;
  {
    py::gil_scoped_release release;
    if (detrend) remove_plane(h);
    sa_ = sa(h);
    rms = h_rms(h);
    slope = h_prime_rms(h);
    slope_fd = h_prime_rms_finite_difference(h);
    psd = window ? psd_2d(windowed(h, radial_hann_window(g))) : psd_2d(h);
    radial = radial_psd(psd);
    // The band: every bin unless told; fewer than 3 bins leaves the fit out.
    try {
      fit = fit_hurst(radial, q_min, std::isfinite(q_max) ? q_max : std::numeric_limits<double>::max());
    } catch (const InputError&) {
      if (q_min > 0.0 || std::isfinite(q_max)) throw;
    }
  }
  out["sa_m"] = sa_;
  out["h_rms_m"] = rms;
  out["h_prime_rms"] = slope;
  out["h_prime_rms_finite_difference"] = slope_fd;
  out["mean_height_m"] = mean_height(h);
  out["psd_q_rad_per_m"] = owned(std::move(radial.q));
  out["psd_c_m4"] = owned(std::move(radial.c));
  out["psd_count"] = radial.count;
  out["psd_2d_m4"] = owned(std::move(psd));
  // A self-affine surface has 0 < H <= 1: a fit outside says the band is not self-affine, and gives no H
  // (as `wearscale surface analyze`: the fit failed, why, and the rest stands).
  std::string failure;
  if (!fit)
    failure = "too few PSD bins in the band for a fit";
  else if (!(fit->hurst > 0.0 && fit->hurst <= 1.0 + 3.0 * fit->hurst_error) || !std::isfinite(fit->hurst_error))
    failure = fmt::format("the PSD over q = {:.4g} … {:.4g} rad/m fits H = {:.3f} ± {:.3f}, outside (0, 1]: that band "
                          "is not self-affine; give the self-affine band as q_min, q_max",
                          fit->q_min, fit->q_max, fit->hurst, fit->hurst_error);
  py::dict status;
  status["status"] = failure.empty() ? "done" : "failed";
  status["reason"] = failure;
  out["hurst_fit"] = status;
  if (fit && failure.empty()) {
    out["hurst"] = fit->hurst;
    out["hurst_error"] = fit->hurst_error;
    out["psd_slope"] = fit->slope;
    out["psd_slope_error"] = fit->slope_error;
    out["fit_q_min_rad_per_m"] = fit->q_min;
    out["fit_q_max_rad_per_m"] = fit->q_max;
    out["fit_bins"] = fit->points;
  }
  return out;
}

py::tuple read(const std::filesystem::path& file, const std::string& dataset, std::optional<double> lx,
               std::optional<double> ly, const std::string& missing) {
  TopographyOptions options;
  options.dataset = dataset;
  options.size.lx = lx;
  options.size.ly = ly;
  options.missing = missing_points_from(missing, "missing");
  MeasuredTopography t;
  {
    py::gil_scoped_release release;
    t = read_measured_topography(file, options);
  }
  py::dict meta;
  meta["lx_m"] = t.heights.grid().lx;
  meta["ly_m"] = t.heights.grid().ly;
  meta["format"] = t.format;
  meta["missing_points"] = t.missing;
  meta["file"] = file;
  return py::make_tuple(owned(std::move(t.heights)), meta);
}

}  // namespace

void bind_surface(py::module_& m) {
  // The keyword defaults: the surface spec's and the topography reader's.
  static const RoughSurfaceSpec spec_defaults{};
  static const TopographyOptions read_defaults{};
  m.def("generate", &generate, py::arg("n"), py::arg("size"), py::arg("hurst") = spec_defaults.hurst,
        py::arg("k_l") = spec_defaults.k_l, py::arg("k_r") = py::none(), py::arg("k_s") = spec_defaults.k_s,
        py::arg("seed") = spec_defaults.seed, py::arg("ny") = py::none(),
        py::arg("ly") = py::none(), py::arg("sa") = py::none(), py::arg("rms") = py::none(),
        py::arg("slope_rms") = py::none(),
        R"(Random self-affine surface with the PSD of Fig. 1.3 (same parameters as `wearscale surface generate`).

n, ny: points along x and y (ny = n unless given; at least 4); size, ly: Lx, Ly [m] (ly = size).
hurst: H in (0, 1]; k_l <= k_r <= k_s: wavenumbers (L/lambda) of the longest wavelength, the
roll-off (default k_l: no plateau) and the shortest (at most the Nyquist wavenumber min(n, ny)/2).
C(k) = 1 on [k_l, k_r), (k/k_r)^(-2(H+1)) on [k_r, k_s], 0 elsewhere; phases from seed.
sa / rms / slope_rms: rescale to Sa (1.4) or h_rms (1.5) [m] or h'_rms (1.6) [1] (at most one).
Returns (heights [m], an (n, ny) float64 array with y fastest, metadata dict).)");
  m.def("analyze", &analyze, py::arg("heights"), py::arg("lx"), py::arg("ly") = -1.0, py::arg("q_min") = 0.0,
        py::arg("q_max") = INFINITY, py::arg("detrend") = false, py::arg("window") = false,
        R"(Roughness and spectrum of a height array [m] of lx x ly metres (ly: square cells).

Returns a dict: sa_m (1.4), h_rms_m (1.5), h_prime_rms (1.6, spectral; and _finite_difference),
the radial PSD (1.9) psd_q_rad_per_m, psd_c_m4, psd_count, the 2D PSD psd_2d_m4 (nx x ny/2+1),
and the Hurst exponent fitted on C ~ q^-2(H+1) in [q_min, q_max] rad/m (every bin by default):
hurst, hurst_error (standard error), psd_slope, psd_slope_error, fit_bins; hurst_fit: {status: "done"
or "failed", reason}: a fit outside 0 < H <= 1 (a band that is not self-affine) gives no hurst.
detrend: subtract the least-squares plane first; window: radial Hann window (measured data).)");
  m.def("read", &read, py::arg("file"), py::arg("dataset") = read_defaults.dataset, py::arg("lx") = py::none(),
        py::arg("ly") = py::none(), py::arg("missing") = std::string(name(read_defaults.missing)),
        R"(A measured or saved topography, its format recognised by content.

Formats: see supported_formats(). dataset: the HDF5 dataset of wearscale's own files; lx, ly [m]
override the file's sizes; missing = "refuse" (default: ValueError naming how many points)
or "fill" (harmonic interpolation). Returns (heights [m], metadata dict with lx_m, ly_m, format).)");
  m.def("supported_formats", &supported_topography_formats, "The topography formats read() understands.");
  m.def("write", [](const std::filesystem::path& file, const InArray& heights, double lx, double ly) {
          const Grid2D g = grid_of(heights, lx, ly, "surface.write");
          return write_surface(file, field_from(heights, g)).string();
        }, py::arg("file"), py::arg("heights"), py::arg("lx"), py::arg("ly") = -1.0,
        "Writes heights [m] as wearscale's HDF5 surface (/surface/height) and its XDMF sidecar; returns the sidecar's path.");
  m.def("sphere", [](std::size_t n, double size, double radius, std::optional<double> cx, std::optional<double> cy) {
          const Grid2D g = Grid2D::square(n, size);
          return owned(sphere(g, radius, cx.value_or(size / 2), cy.value_or(size / 2)));
        }, py::arg("n"), py::arg("size"), py::arg("radius"), py::arg("cx") = py::none(), py::arg("cy") = py::none(),
        "Spherical cap of radius R [m] on an n x n grid of size [m], summit (height 0) at (cx, cy) (the centre), "
        "h = sqrt(R^2 - r^2) - R.");
  m.def("sa", [](const InArray& h, double lx) { return sa(field_from(h, grid_of(h, lx, -1, "sa"))); },
        py::arg("heights"), py::arg("lx") = 1.0, "Sa = <|h - <h>|> (1.4) [m].");
  m.def("h_rms", [](const InArray& h, double lx) { return h_rms(field_from(h, grid_of(h, lx, -1, "h_rms"))); },
        py::arg("heights"), py::arg("lx") = 1.0, "h_rms = sqrt(<(h - <h>)^2>) (1.5) [m].");
  m.def("h_prime_rms",
        [](const InArray& h, double lx, double ly) { return h_prime_rms(field_from(h, grid_of(h, lx, ly, "h_prime_rms"))); },
        py::arg("heights"), py::arg("lx"), py::arg("ly") = -1.0,
        "h'_rms = sqrt(<|grad h|^2>) (1.6), spectral (periodic surfaces), for lx x ly metres.");
}

}  // namespace wearscale::python
