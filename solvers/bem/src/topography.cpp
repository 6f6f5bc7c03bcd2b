#include "wearscale/bem/topography.hpp"

#include "wearscale/core/memory_limit.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

#include <Eigen/Dense>
#include <fmt/format.h>
#include <gsl/gsl_fit.h>

#include "wearscale/bem/spectral_modes.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/fft.hpp"

namespace wearscale::bem {

PlaneFit fit_plane(const RealField& h) {
  const Grid2D& g = h.grid();
  // Normal equations of h ≈ c0 + c1 (x − x̄) + c2 (y − ȳ); centred coordinates
  // keep them well conditioned whatever the offset of the grid.
  const double xm = 0.5 * static_cast<double>(g.nx - 1) * g.dx();
  const double ym = 0.5 * static_cast<double>(g.ny - 1) * g.dy();
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < g.nx; ++i) {
    const double x = g.x(i) - xm;
    for (std::size_t j = 0; j < g.ny; ++j) {
      const Eigen::Vector3d row(1.0, x, g.y(j) - ym);
      ata.noalias() += row * row.transpose();
      atb.noalias() += row * h(i, j);
    }
  }
  const Eigen::Vector3d c = ata.ldlt().solve(atb);
  if (!c.allFinite())
    throw InputError(fmt::format("plane fit failed on a {} × {} topography (too few points or non-finite heights)",
                                 g.nx, g.ny));
  return {c(0) - c(1) * xm - c(2) * ym, c(1), c(2)};
}

PlaneFit remove_plane(RealField& h) {
  const PlaneFit p = fit_plane(h);
  const Grid2D& g = h.grid();
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) h(i, j) -= p.offset + p.slope_x * g.x(i) + p.slope_y * g.y(j);
  return p;
}

RealField radial_hann_window(const Grid2D& g) {
  RealField w(g);
  const double radius = 0.5 * std::min(g.lx, g.ly);
  const double xc = 0.5 * static_cast<double>(g.nx - 1) * g.dx();
  const double yc = 0.5 * static_cast<double>(g.ny - 1) * g.dy();
#pragma omp parallel for
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) {
      const double r = std::hypot(g.x(i) - xc, g.y(j) - yc);
      const double c = std::cos(0.5 * std::numbers::pi * r / radius);
      w(i, j) = r < radius ? c * c : 0.0;  // Hann: cos²(πr/2R) = ½(1 + cos(πr/R))
    }
  return w;
}

RealField windowed(const RealField& h, const RealField& window) {
  if (!(h.grid() == window.grid()))
    throw std::invalid_argument("windowed: the window is on " + window.grid().to_string() + ", the data on " +
                                h.grid().to_string());
  double energy = 0.0;
  for (const double w : window) energy += w * w;
  energy /= static_cast<double>(window.size());  // ⟨w²⟩
  const double norm = 1.0 / std::sqrt(energy);
  RealField out(h.grid());
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = h[k] * window[k] * norm;
  return out;
}

RealField psd_2d(const RealField& h) {
  const Grid2D& g = h.grid();
  ComplexField spectrum = ComplexField::spectrum_of(g);
  FFTPlanCache::global().plan(g)->forward(h, spectrum);  // ĥ (1.7) in 2D
  const double n = static_cast<double>(g.size());
  const double a = g.area() / (n * n);  // A = LxLy/(nx²ny²)
  RealField c(g, Layout::Spectral);
  for (std::size_t k = 0; k < c.size(); ++k) c[k] = a * std::norm(spectrum[k]);  // C = A|ĥ|²  (1.9), (8.5)
  return c;
}

double radial_psd_bins(const Grid2D& g) {
  double k_max = 0.0;
  for (std::size_t i = 0; i < g.nx; ++i) k_max = std::max(k_max, radial_wavenumber(g, i, g.spectral_ny() - 1));
  for (std::size_t j = 0; j < g.spectral_ny(); ++j) k_max = std::max(k_max, radial_wavenumber(g, g.nx / 2, j));
  return std::floor(k_max * (1.0 + wavenumber_slack)) + 1.0;
}

RadialPsd radial_psd(const RealField& psd) {
  if (psd.layout() != Layout::Spectral) throw std::invalid_argument("radial_psd: expects a spectral PSD (psd_2d)");
  const Grid2D& g = psd.grid();
  const double unit = wavenumber_unit(g);
  const double bin_count = radial_psd_bins(g);
  require_memory(24.0 * bin_count, fmt::format("the radial PSD of a {} × {} topography of {:g} × {:g} m ({:.3g} |q| bins)",
                                               g.nx, g.ny, g.lx, g.ly, bin_count),
                 "the bins grow with the aspect ratio lx/ly: check the sizes");
  const auto bins = static_cast<std::size_t>(bin_count);
  std::vector<double> sum_q(bins, 0.0), sum_c(bins, 0.0), weight(bins, 0.0);
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.spectral_ny(); ++j) {
      if (i == 0 && j == 0) continue;  // the mean height
      const double k = radial_wavenumber(g, i, j);
      const auto b = std::min(bins - 1, static_cast<std::size_t>(std::floor(k * (1.0 + wavenumber_slack))));
      const double m = mode_multiplicity(g, j);
      sum_q[b] += m * k * unit;
      sum_c[b] += m * psd(i, j);
      weight[b] += m;
    }
  RadialPsd out;
  for (std::size_t b = 0; b < bins; ++b) {
    if (weight[b] == 0.0) continue;
    out.q.push_back(sum_q[b] / weight[b]);
    out.c.push_back(sum_c[b] / weight[b]);
    out.count.push_back(static_cast<std::size_t>(weight[b]));
  }
  return out;
}

HurstFit fit_hurst(const RadialPsd& radial, double q_min, double q_max) {
  if (!(std::isfinite(q_min) && std::isfinite(q_max) && q_min >= 0.0 && q_min < q_max))
    throw InputError(fmt::format("Hurst fit: band q_min = {:g}, q_max = {:g} rad/m is not valid; allowed: "
                                 "0 ≤ q_min < q_max (finite)", q_min, q_max));
  double c_max = 0.0;
  for (const double c : radial.c) c_max = std::max(c_max, c);
  const double floor = 1e-20 * c_max;  // below it a bin is numerically empty
  std::vector<double> x, y, w;
  double q_first = 0.0, q_last = 0.0;
  for (std::size_t b = 0; b < radial.q.size(); ++b) {
    if (radial.q[b] < q_min || radial.q[b] > q_max || !(radial.c[b] > floor) || radial.q[b] <= 0.0) continue;
    if (x.empty()) q_first = radial.q[b];
    q_last = radial.q[b];
    x.push_back(std::log(radial.q[b]));
    y.push_back(std::log(radial.c[b]));
    w.push_back(static_cast<double>(radial.count[b]));
  }
  const std::size_t n = x.size();
  if (n < 3)
    throw InputError(fmt::format("Hurst fit: the band q_min = {:g} to q_max = {:g} rad/m holds {} PSD bin(s) with "
                                 "power; allowed: a band of at least 3 bins", q_min, q_max, n));
  double c0 = 0.0, c1 = 0.0, cov00 = 0.0, cov01 = 0.0, cov11 = 0.0, chisq = 0.0;
  gsl_fit_wlinear(x.data(), 1, w.data(), 1, y.data(), 1, n, &c0, &c1, &cov00, &cov01, &cov11, &chisq);
  // Weights are relative: scale the covariance by the reduced χ².
  const double s2 = chisq / static_cast<double>(n - 2);
  HurstFit fit;
  fit.slope = c1;                           // β in C ∝ q^β   (1.10)
  fit.slope_error = std::sqrt(cov11 * s2);
  fit.hurst = -0.5 * c1 - 1.0;              // H = −β/2 − 1 (2D)
  fit.hurst_error = 0.5 * fit.slope_error;  // σ_H = σ_β/2
  fit.intercept = c0;
  fit.points = n;
  fit.q_min = q_first;
  fit.q_max = q_last;
  return fit;
}

}  // namespace wearscale::bem
