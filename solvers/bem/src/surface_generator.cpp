#include "wearscale/bem/surface_generator.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "wearscale/bem/spectral_modes.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/fft.hpp"
#include "wearscale/core/memory_limit.hpp"

namespace wearscale::bem {

namespace {

constexpr const char* source = "rough surface";

std::string num(double v) { return fmt::format("{:g}", v); }

/// Uniform in [0, 1) from the top 53 bits: the same on every standard library
/// (std::uniform_real_distribution is not specified bit for bit).
double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

bool at_least(double k, double bound) { return k >= bound * (1.0 - wavenumber_slack); }
bool at_most(double k, double bound) { return k <= bound * (1.0 + wavenumber_slack); }

}  // namespace

void validate(const RoughSurfaceSpec& s) {
  const Grid2D& g = s.grid;
  if (g.nx < 4 || g.ny < 4)
    throw InputError::at_key(source, "grid", fmt::format("{} × {}", g.nx, g.ny), "too few points",
                             "at least 4 × 4 points");
  if (!(std::isfinite(g.lx) && g.lx > 0.0))
    throw InputError::at_key(source, "lx", num(g.lx), "the side of the surface must be a positive length", "> 0 m");
  if (!(std::isfinite(g.ly) && g.ly > 0.0))
    throw InputError::at_key(source, "ly", num(g.ly), "the side of the surface must be a positive length", "> 0 m");
  if (!(s.hurst > 0.0 && s.hurst <= 1.0))
    throw InputError::at_key(source, "hurst", num(s.hurst), "Hurst exponent out of range", "(0, 1]");
  if (!(std::isfinite(s.k_l) && s.k_l > 0.0))
    throw InputError::at_key(source, "k_l", num(s.k_l), "the longest wavelength's wavenumber must be positive",
                             "0 < k_l ≤ k_r ≤ k_s");
  if (!(std::isfinite(s.k_r) && s.k_r >= s.k_l))
    throw InputError::at_key(source, "k_r", num(s.k_r), fmt::format("roll-off wavenumber below k_l = {:g}", s.k_l),
                             "0 < k_l ≤ k_r ≤ k_s");
  if (!(std::isfinite(s.k_s) && s.k_s >= s.k_r))
    throw InputError::at_key(source, "k_s", num(s.k_s),
                             fmt::format("shortest-wavelength wavenumber below k_r = {:g} (k_l = {:g})", s.k_r, s.k_l),
                             "0 < k_l ≤ k_r ≤ k_s");
  const double nyquist = nyquist_wavenumber(g);
  if (!at_most(s.k_s, nyquist))
    throw InputError::at_key(source, "k_s", num(s.k_s),
                             fmt::format("above the Nyquist wavenumber of the {} × {} grid", g.nx, g.ny),
                             fmt::format("k_s ≤ {:g} (min(nx, ny)/2 on a square domain)", nyquist));
}

double target_psd(const RoughSurfaceSpec& s, double k) {
  if (!at_least(k, s.k_l) || !at_most(k, s.k_s)) return 0.0;     // outside [q_l, q_s]: Fig. 1.3
  if (!at_least(k, s.k_r)) return 1.0;                            // plateau q_l ≤ q < q_r
  return std::pow(k / s.k_r, -2.0 * (s.hurst + 1.0));              // C ∝ q^β, β = −2(H+1)  (1.10)
}

void rough_spectrum(const RoughSurfaceSpec& s, std::size_t first, std::size_t rows, std::complex<double>* out) {
  validate(s);
  const Grid2D& g = s.grid;
  if (first + rows > g.nx) throw std::invalid_argument("rough_spectrum: rows beyond the grid");
  const double n = static_cast<double>(g.size());
  const double a = g.area() / (n * n);  // A = LxLy/(nx²ny²)   (1.9)
  const std::size_t cols = g.spectral_ny();
  auto mode = [&](std::size_t i, std::size_t j, double u) {
    const double amplitude = std::sqrt(target_psd(s, radial_wavenumber(g, i, j)) / a);  // |ĥ| = √(C/A)  (1.9)
    return std::polar(amplitude, 2.0 * std::numbers::pi * u);
  };
  // One phase per r2c mode, in storage order, whether used or not: the seed
  // alone fixes the surface. A slab of rows starts `first` rows into the stream.
  std::mt19937_64 rng(s.seed);
  rng.discard(static_cast<unsigned long long>(first * cols));
  for (std::size_t i = 0; i < rows; ++i)
    for (std::size_t j = 0; j < cols; ++j) out[i * cols + j] = mode(first + i, j, uniform01(rng));
  // Columns that are their own mirror image (j = 0, and j = ny/2 for even ny)
  // hold both ĥ(kx, ky) and ĥ(−kx, ky) = conj ĥ(kx, −ky): make them conjugate,
  // and the self-conjugate modes real (a random sign keeps |ĥ|). Mirror rows
  // outside the slab are drawn again from their place in the stream.
  std::vector<std::size_t> mirrored;
  for (std::size_t j = 0; j < cols; ++j)
    if (mode_multiplicity(g, j) == 1.0) mirrored.push_back(j);
  // The mirror rows before the slab, [lo, first): ascending, so one generator walks to them.
  const std::size_t last = first + rows;  // rows i ≥ nx − first have mirrors nx − i < first... (i > 0)
  const std::size_t lo = last > 0 && last < g.nx ? g.nx - last + 1 : 1;
  std::vector<std::complex<double>> before;  // mode (m, mirrored[c]) at (m − lo)·|mirrored| + c
  if (rows > 0 && lo < first) {
    std::mt19937_64 walk(s.seed);
    std::size_t at = 0;  // stream position of the next draw
    before.reserve((first - lo) * mirrored.size());
    for (std::size_t m = lo; m < first; ++m)
      for (const std::size_t j : mirrored) {
        walk.discard(static_cast<unsigned long long>(m * cols + j - at));
        before.push_back(mode(m, j, uniform01(walk)));
        at = m * cols + j + 1;
      }
  }
  for (std::size_t i = first; i < last; ++i) {
    const std::size_t mirror = (g.nx - i) % g.nx;
    if (mirror > i) continue;
    for (std::size_t c = 0; c < mirrored.size(); ++c) {
      auto& z = out[(i - first) * cols + mirrored[c]];
      if (mirror == i)
        z = std::abs(z) * (z.real() >= 0.0 ? 1.0 : -1.0);
      else if (mirror >= first)
        z = std::conj(out[(mirror - first) * cols + mirrored[c]]);
      else
        z = std::conj(before[(mirror - lo) * mirrored.size() + c]);
    }
  }
}

RealField generate_surface(const RoughSurfaceSpec& s) {
  const Grid2D& g = s.grid;
  validate(s);
  // The spectrum and the heights, checked before either is allocated (every caller: `surface generate`, contact,
  // wear maps, Python); `surface generate` checks 48 B per point first, with its copies.
  require_memory(24.0 * static_cast<double>(g.size()), fmt::format("a rough surface of {} × {} points", g.nx, g.ny),
                 "use a smaller grid");
  ComplexField spectrum = ComplexField::spectrum_of(g);
  rough_spectrum(s, 0, g.nx, spectrum.data());
  RealField h(g);
  FFTPlanCache::global().plan(g)->backward(spectrum, h);  // (1.8)
  return h;
}

double predicted_hprime_rms(const RoughSurfaceSpec& s, RoughnessMeasure measure, double target) {
  validate(s);
  if (measure == RoughnessMeasure::HPrimeRms) return target;
  const Grid2D& g = s.grid;
  const std::size_t cols = g.spectral_ny();
  // ⟨|∇h|²⟩/⟨h²⟩ = Σ w q² C / Σ w C over the modes (Parseval; |ĥ|² ∝ C), in a fixed order.
  double power = 0.0, slope = 0.0;
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < cols; ++j) {
      const double c = mode_multiplicity(g, j) * target_psd(s, radial_wavenumber(g, i, j));
      const double qx = g.wavenumber_x(i), qy = g.wavenumber_y(j);
      power += c;
      slope += c * (qx * qx + qy * qy);
    }
  if (!(power > 0.0)) return 0.0;
  const double h_rms = measure == RoughnessMeasure::HRms ? target : target * std::sqrt(std::numbers::pi / 2.0);
  return h_rms * std::sqrt(slope / power);
}

RoughnessTargetProblem roughness_target_problem(const RoughSurfaceSpec& s, RoughnessMeasure measure, double target) {
  validate(s);
  const double side = std::min(s.grid.lx, s.grid.ly);
  const double most = measure == RoughnessMeasure::HPrimeRms ? max_hprime_rms : side;
  if (!(std::isfinite(target) && target > 0.0 && target <= most))
    return {"out of range", measure == RoughnessMeasure::HPrimeRms
                                ? fmt::format("(0, {:g}]", max_hprime_rms)
                                : fmt::format("(0, {:g}] m (the shorter side of the surface)", side)};
  const double slope = predicted_hprime_rms(s, measure, target);
  if (!(slope <= max_hprime_rms))
    return {fmt::format("gives an RMS slope h'_RMS = {:.3g} on this spectrum (heights rising more than {:g} cell "
                        "widths per cell)",
                        slope, max_hprime_rms),
            fmt::format("h'_RMS ≤ {:g}, here {} ≤ {:.3g}", max_hprime_rms, name(measure),
                        target * max_hprime_rms / slope)};
  return {};
}

void check_roughness_target(const RoughSurfaceSpec& s, RoughnessMeasure measure, double target) {
  if (const auto p = roughness_target_problem(s, measure, target); !p.problem.empty())
    throw InputError::at_key(source, name(measure), num(target), p.problem, p.allowed);
}

RealField generate_surface(const RoughSurfaceSpec& spec, RoughnessMeasure measure, double target) {
  check_roughness_target(spec, measure, target);
  RealField h = generate_surface(spec);
  rescale(h, measure, target);
  if (measure == RoughnessMeasure::Sa) {  // predicted about only: the surface itself is held to the bound
    const double slope = h_prime_rms(h);
    if (!(slope <= max_hprime_rms))
      throw InputError::at_key(source, name(measure), num(target),
                               fmt::format("gives an RMS slope h'_RMS = {:.3g}", slope),
                               fmt::format("h'_RMS ≤ {:g}", max_hprime_rms));
  }
  return h;
}

RealField sphere(const Grid2D& grid, double radius, double cx, double cy) {
  return sphere_rows(grid, 0, grid.nx, radius, cx, cy);
}

RealField sphere_rows(const Grid2D& grid, std::size_t first, std::size_t rows, double radius, double cx, double cy) {
  if (!(std::isfinite(radius) && radius > 0.0))
    throw InputError::at_key("sphere", "radius", num(radius), "the radius must be a positive length", "> 0 m");
  if (!std::isfinite(cx) || !std::isfinite(cy))
    throw InputError::at_key("sphere", "centre", fmt::format("({:g}, {:g})", cx, cy), "not finite", "finite lengths");
  if (first + rows > grid.nx) throw std::invalid_argument("sphere_rows: rows beyond the grid");
  require_memory(8.0 * static_cast<double>(rows) * static_cast<double>(grid.ny),
                 fmt::format("a sphere of {} × {} points", rows, grid.ny), "use a smaller grid");
  RealField h(grid.slab(rows));
  // Nearest periodic image: the offset folded into [−L/2, L/2).
  auto fold = [](double d, double l) { return d - l * std::floor(d / l + 0.5); };
  const double r2_max = radius * radius;
#pragma omp parallel for
  for (std::size_t i = 0; i < rows; ++i) {
    const double dx = fold(grid.x(first + i) - cx, grid.lx);
    for (std::size_t j = 0; j < grid.ny; ++j) {
      const double dy = fold(grid.y(j) - cy, grid.ly);
      const double r2 = dx * dx + dy * dy;
      h(i, j) = (r2 < r2_max ? std::sqrt(r2_max - r2) : 0.0) - radius;  // cap √(R² − r²) − R, clipped to −R
    }
  }
  return h;
}

RealField plane(const Grid2D& grid, double value) { return RealField(grid, Layout::Physical, value); }

RealField tilted_plane(const Grid2D& grid, double slope_x, double slope_y) {
  RealField h(grid);
  for (std::size_t i = 0; i < grid.nx; ++i)
    for (std::size_t j = 0; j < grid.ny; ++j) h(i, j) = slope_x * grid.x(i) + slope_y * grid.y(j);
  return h;
}

RealField add(const RealField& a, const RealField& b) {
  if (!(a.grid() == b.grid()) || a.layout() != b.layout())
    throw InputError(fmt::format("cannot add surfaces on different grids: {} and {}", a.grid().to_string(),
                                 b.grid().to_string()));
  RealField sum(a);
  for (std::size_t k = 0; k < sum.size(); ++k) sum[k] += b[k];
  return sum;
}

}  // namespace wearscale::bem
