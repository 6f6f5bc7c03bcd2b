#pragma once
// Spectral analysis of a topography (thesis §1.1.2 and §8.1.1): levelling,
// radial Hann window, PSD (1.9)/(8.5), radial PSD and Hurst exponent fit.
//
// Measured data: remove_plane, then windowed(h, radial_hann_window(grid)),
// then psd_2d, radial_psd, fit_hurst. Periodic generated surfaces need no window.
#include <cstddef>
#include <vector>

#include "wearscale/core/field.hpp"

namespace wearscale::bem {

/// A plane h = offset + slope_x·x + slope_y·y (x_i = i·dx, y_j = j·dy).
struct PlaneFit {
  double offset = 0.0;
  double slope_x = 0.0;
  double slope_y = 0.0;
};

/// Least-squares plane through all points of `h` (normal equations, Eigen).
PlaneFit fit_plane(const RealField& h);

/// Subtracts the least-squares plane from `h` and returns it; afterwards
/// h has zero mean and no tilt.
PlaneFit remove_plane(RealField& h);

/// Radially symmetric Hann window, centred on the middle of the data
/// ((nx−1)dx/2, (ny−1)dy/2) so both edges are treated alike:
///   w(r) = cos²(πr / 2R) = ½(1 + cos(πr/R))  for r < R = min(Lx, Ly)/2,
///   w(r) = 0                                for r ≥ R (corners are dropped).
/// w = 1 at the centre.
RealField radial_hann_window(const Grid2D& grid);

/// h·w / √⟨w²⟩: the windowed data, normalised by the window's energy so that
/// the PSD level (and h_RMS) of a field uncorrelated with the window is
/// preserved: C of the windowed data = C(h·w)/⟨w²⟩.
RealField windowed(const RealField& h, const RealField& window);

/// C(q) = A |ĥ(q)|², A = LxLy/(nx²ny²)   (1.9), (8.5)
/// on the r2c half-grid (Layout::Spectral, nx × (ny/2+1)); mode (i, j) is at
/// q = (grid.wavenumber_x(i), grid.wavenumber_y(j)).
RealField psd_2d(const RealField& h);

/// Isotropic PSD C(|q|): the 2D PSD averaged over annuli of width Δq = 2π/L
/// (L = longer side, spectral_modes.hpp); bin b holds the modes with
/// b·Δq ≤ |q| < (b+1)·Δq, counted over the full spectrum (the r2c columns
/// 0 < j < ny/2 stand for two modes). Empty bins and the zero mode are skipped.
struct RadialPsd {
  std::vector<double> q;             ///< mean |q| of the modes in the bin [rad/m]
  std::vector<double> c;             ///< mean C over those modes [m⁴]
  std::vector<std::size_t> count;    ///< number of modes in the bin
};

/// Radial average of a PSD made by psd_2d (std::invalid_argument if `psd` is not spectral).
RadialPsd radial_psd(const RealField& psd);
/// How many |q| bins radial_psd makes on `grid` (1 + the largest radial wavenumber in units of 2π/lx): it
/// grows with the aspect ratio lx/ly, so a caller checks it against the memory limit first (24 bytes a bin).
/// A double: a 4096-point side over 1 nm beside 8 points over a metre asks for about 10^12 bins.
double radial_psd_bins(const Grid2D& grid);

/// Power law C ∝ q^β fitted on the radial PSD in a band: H = −β/2 − 1 (2D, Fig. 1.3).
struct HurstFit {
  double hurst = 0.0;
  double hurst_error = 0.0;  ///< standard error σ_H = σ_β / 2
  double slope = 0.0;        ///< β
  double slope_error = 0.0;  ///< σ_β
  double intercept = 0.0;    ///< ln C at q = 1 rad/m
  std::size_t points = 0;    ///< bins used
  double q_min = 0.0, q_max = 0.0;  ///< band actually used (first and last bin)
};

/// Straight line ln C = a + β ln q through the bins with q_min ≤ q ≤ q_max
/// (gsl_fit_wlinear), weighted by the number of modes per bin (the variance of
/// ln of a mean of n independent modes is ∝ 1/n); the covariance is scaled by
/// the reduced χ², so σ_β reflects the actual scatter about the line.
/// Bins with C ≤ 1e-20 × the largest C of the radial PSD are numerically empty
/// (e.g. outside the band of a generated surface) and are skipped.
/// InputError if the band is not 0 ≤ q_min < q_max or holds fewer than 3 bins.
HurstFit fit_hurst(const RadialPsd& radial, double q_min, double q_max);

}  // namespace wearscale::bem
