#include "wearscale/core/savitzky_golay.hpp"

#include <cstddef>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>
#include <gsl/gsl_multifit.h>

namespace wearscale {

namespace {
template <class T, void (*Free)(T*)>
struct Freer {
  void operator()(T* p) const { Free(p); }
};
using Matrix = std::unique_ptr<gsl_matrix, Freer<gsl_matrix, gsl_matrix_free>>;
using Vector = std::unique_ptr<gsl_vector, Freer<gsl_vector, gsl_vector_free>>;
using Workspace = std::unique_ptr<gsl_multifit_linear_workspace,
                                  Freer<gsl_multifit_linear_workspace, gsl_multifit_linear_free>>;
}  // namespace

std::vector<double> savitzky_golay(std::span<const double> x, std::span<const double> y, int window, int degree) {
  const std::size_t n = x.size();
  if (y.size() != n) throw std::invalid_argument(fmt::format("savitzky_golay: {} abscissae for {} values", n, y.size()));
  if (window < 1 || window % 2 == 0 || degree < 0 || degree >= window)
    throw std::invalid_argument(
        fmt::format("savitzky_golay: window {} and degree {}; allowed: an odd window > degree ≥ 0", window, degree));
  const auto w = static_cast<std::size_t>(window);
  if (n < w) throw std::invalid_argument(fmt::format("savitzky_golay: {} points for a window of {}", n, window));
  for (std::size_t i = 1; i < n; ++i)
    if (!(x[i] > x[i - 1])) throw std::invalid_argument("savitzky_golay: abscissae not strictly increasing");

  const auto p = static_cast<std::size_t>(degree) + 1;
  Matrix design(gsl_matrix_alloc(w, p)), cov(gsl_matrix_alloc(p, p));
  Vector values(gsl_vector_alloc(w)), coef(gsl_vector_alloc(p));
  Workspace work(gsl_multifit_linear_alloc(w, p));
  const std::size_t half = w / 2;
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    // The window: centred on i, or the first/last w points near the ends.
    const std::size_t first = i < half ? 0 : (i + half >= n ? n - w : i - half);
    // Powers of (x - x_i) scaled by the window's half-width: a well-conditioned
    // basis whose constant coefficient is the smoothed value at x_i.
    const double scale = 0.5 * (x[first + w - 1] - x[first]);
    for (std::size_t r = 0; r < w; ++r) {
      const double t = (x[first + r] - x[i]) / scale;
      double power = 1.0;
      for (std::size_t c = 0; c < p; ++c, power *= t) gsl_matrix_set(design.get(), r, c, power);
      gsl_vector_set(values.get(), r, y[first + r]);
    }
    double chisq = 0.0;
    gsl_multifit_linear(design.get(), values.get(), coef.get(), cov.get(), &chisq, work.get());
    out[i] = gsl_vector_get(coef.get(), 0);
  }
  return out;
}

}  // namespace wearscale
