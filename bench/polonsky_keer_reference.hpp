#pragma once
// A textbook Polonsky–Keer solver (Polonsky & Keer, Wear 231, 1999), written
// as the paper states it, for side-by-side runs against NormalContact: each
// iteration convolves twice, u = K p and r = K t (two r2c + c2r pairs), with
// the step τ = Σ g t / Σ r t over the contact. The same convergence measure
// as NormalContact (ε = Σ p|g| / (Σ p · h_rms)) so that both stop alike.
// Bench-only code: not part of the library.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "wearscale/bem/half_space.hpp"
#include "wearscale/bem/roughness.hpp"

namespace wearscale::bench {

struct ReferenceResult {
  int iterations = 0;
  double error = 0.0, contact_fraction = 0.0;
};

inline ReferenceResult polonsky_keer_reference(const RealField& h, double e_star, double p0, double tolerance,
                                               int max_iterations) {
  const Grid2D& grid = h.grid();
  const std::size_t n = grid.size();
  const bem::HalfSpace body = bem::HalfSpace::normal(grid, e_star);
  auto w = body.workspace();
  RealField p(grid, Layout::Physical, p0), u(grid), t(grid), r(grid), g(grid);
  const double scale = bem::h_rms(h);
  double g_old = 1.0;
  bool delta = false;
  for (int it = 0; it < max_iterations; ++it) {
    body.normal_displacement(p, u, w);
    double n_s = 0.0, mean = 0.0;
    for (std::size_t k = 0; k < n; ++k)
      if (p[k] > 0.0) n_s += 1.0, mean += u[k] - h[k];
    mean /= n_s;
    double g_sum = 0.0, err = 0.0, p_sum = 0.0;
    bool penetrates = false;
    for (std::size_t k = 0; k < n; ++k) {
      g[k] = u[k] - h[k] - mean;
      if (p[k] > 0.0) g_sum += g[k] * g[k], err += p[k] * std::abs(g[k]);
      else penetrates = penetrates || g[k] < 0.0;
      p_sum += p[k];
    }
    err /= p_sum * scale;
    if (err < tolerance && !penetrates) {
      double c = 0.0;
      for (double v : p) c += v > 0.0 ? 1.0 : 0.0;
      return {it, err, c / static_cast<double>(n)};
    }
    for (std::size_t k = 0; k < n; ++k) t[k] = p[k] > 0.0 ? g[k] + (delta ? g_sum / g_old : 0.0) * t[k] : 0.0;
    g_old = g_sum;
    body.normal_displacement(t, r, w);  // the second convolution
    double r_mean = 0.0;
    for (std::size_t k = 0; k < n; ++k)
      if (p[k] > 0.0) r_mean += r[k];
    r_mean /= n_s;
    double gt = 0.0, rt = 0.0;
    for (std::size_t k = 0; k < n; ++k)
      if (p[k] > 0.0) gt += g[k] * t[k], rt += (r[k] - r_mean) * t[k];
    const double tau = gt / rt;
    for (std::size_t k = 0; k < n; ++k)
      if (p[k] > 0.0) p[k] = std::max(p[k] - tau * t[k], 0.0);
    bool overlap = false;
    for (std::size_t k = 0; k < n; ++k)
      if (p[k] == 0.0 && g[k] < 0.0) p[k] -= tau * g[k], overlap = true;
    delta = !overlap;
    double sum = 0.0;
    for (double v : p) sum += v;
    const double a = p0 * static_cast<double>(n) / sum;
    for (double& v : p) v *= a;
  }
  throw std::runtime_error("textbook Polonsky–Keer: no convergence");
}

}  // namespace wearscale::bench
