#include "wearscale/bem/roughness.hpp"

#include <cmath>
#include <complex>
#include <limits>

#include <fmt/format.h>

#include "wearscale/bem/spectral_modes.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/fft.hpp"

namespace wearscale::bem {

// Sums run serially in storage order: the statistics of a surface are then
// bit-for-bit the same whatever the number of threads.

double mean_height(const RealField& h) {
  double sum = 0.0;
  for (const double v : h) sum += v;
  return sum / static_cast<double>(h.size());  // (1.3)
}

double sa(const RealField& h) {
  const double m = mean_height(h);
  double sum = 0.0;
  for (const double v : h) sum += std::abs(v - m);
  return sum / static_cast<double>(h.size());  // (1.4)
}

double h_rms(const RealField& h) {
  const double m = mean_height(h);
  double sum = 0.0;
  for (const double v : h) sum += (v - m) * (v - m);
  return std::sqrt(sum / static_cast<double>(h.size()));  // (1.5)
}

double h_prime_rms(const RealField& h) {
  const Grid2D& g = h.grid();
  ComplexField spectrum = ComplexField::spectrum_of(g);
  FFTPlanCache::global().plan(g)->forward(h, spectrum);
  const std::size_t cols = g.spectral_ny();
  const double sum = hermitian_sum<double>(g, [&](std::size_t m, double w, double& s) {
    const double qx = g.wavenumber_x(m / cols), qy = g.wavenumber_y(m % cols);
    s += w * (qx * qx + qy * qy) * std::norm(spectrum[m]);
  });
  const double n = static_cast<double>(g.size());
  return std::sqrt(sum / (n * n));  // (1.6) via Parseval: ⟨|∇h|²⟩ = Σ|q|²|ĥ|²/N²
}

double h_prime_rms_finite_difference(const RealField& h) {
  const Grid2D& g = h.grid();
  if (g.nx < 2 || g.ny < 2)
    throw InputError(fmt::format("h'_RMS by finite differences needs at least 2 × 2 points, got {} × {}", g.nx, g.ny));
  double sx = 0.0, sy = 0.0;
  for (std::size_t i = 0; i + 1 < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) {
      const double d = h(i + 1, j) - h(i, j);
      sx += d * d;
    }
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j + 1 < g.ny; ++j) {
      const double d = h(i, j + 1) - h(i, j);
      sy += d * d;
    }
  const double mx = sx / (static_cast<double>((g.nx - 1) * g.ny) * g.dx() * g.dx());
  const double my = sy / (static_cast<double>(g.nx * (g.ny - 1)) * g.dy() * g.dy());
  return std::sqrt(mx + my);  // (1.6) with ∂h by forward differences
}

double roughness(const RealField& h, RoughnessMeasure measure) {
  switch (measure) {
    case RoughnessMeasure::Sa: return sa(h);
    case RoughnessMeasure::HRms: return h_rms(h);
    case RoughnessMeasure::HPrimeRms: return h_prime_rms(h);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

const char* name(RoughnessMeasure measure) {
  switch (measure) {
    case RoughnessMeasure::Sa: return "Sa";
    case RoughnessMeasure::HRms: return "h_rms";
    case RoughnessMeasure::HPrimeRms: return "h_prime_rms";
  }
  return "?";
}

void rescale(RealField& h, RoughnessMeasure measure, double target) {
  rescale(h, measure, target, [&] { return roughness(h, measure); });
}

void rescale(RealField& h, RoughnessMeasure measure, double target, const std::function<double()>& current_value) {
  if (!std::isfinite(target) || target <= 0.0)
    throw InputError(fmt::format("rescale: target {} = {:g} is not allowed; allowed: > 0 (finite)", name(measure),
                                 target));
  const double current = current_value();
  if (!std::isfinite(current) || current <= 0.0)
    throw InputError(fmt::format("rescale: the surface has {} = {:g} (flat or not finite), so it cannot be scaled to {:g}",
                                 name(measure), current, target));
  const double factor = target / current;
  for (double& v : h) v *= factor;
}

}  // namespace wearscale::bem
