#include "wearscale/bem/slab_surface.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "wearscale/bem/spectral_modes.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/mpi.hpp"

namespace wearscale::bem {

namespace {
void check_shape(const Grid2D& g, const SlabFFT& fft) {
  if (g.nx != fft.nx() || g.ny != fft.ny())
    throw std::invalid_argument(fmt::format("slab surface: a {} grid on a {}×{} transform", g.to_string(), fft.nx(),
                                            fft.ny()));
}
}  // namespace

RealField generate_surface_slab(const RoughSurfaceSpec& spec, SlabFFT& fft) {
  const Grid2D& g = spec.grid;
  check_shape(g, fft);
  rough_spectrum(spec, fft.first_row(), fft.rows(), fft.spectrum());
  fft.backward();  // (1.8)
  RealField h(g.slab(fft.rows()));
  fft.store(h.data(), 1.0 / static_cast<double>(g.size()));
  return h;
}

RealField generate_surface_slab(const RoughSurfaceSpec& spec, RoughnessMeasure measure, double target, SlabFFT& fft) {
  RealField h = generate_surface_slab(spec, fft);
  rescale(h, measure, target, [&] { return roughness_slab(h, spec.grid, measure, fft); });
  return h;
}

double roughness_slab(const RealField& h, const Grid2D& g, RoughnessMeasure measure, SlabFFT& fft) {
  check_shape(g, fft);
  if (!(h.grid() == g.slab(fft.rows()))) throw std::invalid_argument("roughness_slab: not this rank's rows");
  const double n = static_cast<double>(g.size());
  if (measure == RoughnessMeasure::HPrimeRms) {  // (1.6) via Parseval, as h_prime_rms
    fft.load(h.data());
    fft.forward();
    const auto* spectrum = fft.spectrum();
    const std::size_t cols = g.spectral_ny(), first = fft.first_row();
    const double local = hermitian_sum<double>(h.grid(), [&](std::size_t m, double w, double& s) {
      const double qx = g.wavenumber_x(first + m / cols), qy = g.wavenumber_y(m % cols);
      s += w * (qx * qx + qy * qy) * std::norm(spectrum[m]);
    });
    return std::sqrt(mpi::sum(local) / (n * n));
  }
  // Sa (1.4), h_RMS (1.5): sums in storage order on each rank, ranks in order.
  double total = 0.0;
  for (const double v : h) total += v;
  const double mean = mpi::sum(total) / n;
  double dev = 0.0;
  if (measure == RoughnessMeasure::Sa) {
    for (const double v : h) dev += std::abs(v - mean);
    return mpi::sum(dev) / n;
  }
  for (const double v : h) dev += (v - mean) * (v - mean);
  return std::sqrt(mpi::sum(dev) / n);
}

}  // namespace wearscale::bem
