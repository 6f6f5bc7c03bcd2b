#pragma once
// Rough surfaces with a prescribed power spectral density (thesis §1.1.2,
// Fig. 1.3 and 5.1), and simple deterministic surfaces (sphere, planes) to
// combine with them.
//
// Heights are in the length unit of the grid (metres). A surface is a
// RealField on a Grid2D; the summit of a surface is its highest point.
#include <complex>
#include <cstddef>
#include <cstdint>
#include <string>

#include "wearscale/bem/roughness.hpp"
#include "wearscale/core/field.hpp"

namespace wearscale::bem {

/// Target PSD of Fig. 1.3, with k the radial wavenumber of spectral_modes.hpp
/// (q = 2πk/L):
///   C = 0                       for k < k_l or k > k_s,
///   C = 1 (plateau)             for k_l ≤ k < k_r,
///   C = (k/k_r)^(−2(H+1))       for k_r ≤ k ≤ k_s   (slope β = −2(H+1) in 2D).
/// k_r = k_l drops the plateau, as in the thesis.
struct RoughSurfaceSpec {
  Grid2D grid;
  double hurst = 0.8;   ///< H in (0, 1]
  double k_l = 1.0;     ///< longest wavelength: λ_l = L/k_l
  double k_r = 1.0;     ///< roll-off: λ_r = L/k_r
  double k_s = 16.0;    ///< shortest wavelength: λ_s = L/k_s, at most the Nyquist wavenumber
  std::uint64_t seed = 0;
};

/// InputError naming the parameter, its value and the allowed range if
/// H ∉ (0, 1], not 0 < k_l ≤ k_r ≤ k_s, k_s above the Nyquist wavenumber
/// (min(nx, ny)/2 on a square domain), the grid smaller than 4 × 4 or its
/// sides not finite and > 0.
void validate(const RoughSurfaceSpec& spec);

/// The target PSD of `spec` at radial wavenumber k, with plateau value 1
/// (the scale is arbitrary: rescale the surface to the roughness you want).
double target_psd(const RoughSurfaceSpec& spec, double k);

/// A random surface whose PSD (1.9), computed by psd_2d, equals target_psd
/// at every mode: amplitudes |ĥ| = √(C/A) with A = LxLy/(nx²ny²), phases
/// uniform in [0, 2π) from std::mt19937_64(seed), drawn one per r2c mode in
/// storage order (so a seed gives the same surface on every platform), made
/// Hermitian-consistent so that the inverse DFT (1.8) is real. Self-conjugate
/// modes (on the axes at k = 0 or the Nyquist frequency) take a random sign
/// instead of a phase. The mean height is zero.
RealField generate_surface(const RoughSurfaceSpec& spec);

/// Rows [first, first + rows) of the r2c spectrum that generate_surface
/// transforms (`out`: rows × (ny/2 + 1) modes), for a surface made in slabs
/// (slab_surface.hpp). The phases are drawn from their places in the seed's
/// stream: mt19937_64 skips ahead by discard(), linear in the skipped draws, so
/// a slab costs O(first · ny) draws besides its own.
void rough_spectrum(const RoughSurfaceSpec& spec, std::size_t first, std::size_t rows, std::complex<double>* out);

/// The cap of sphere() on rows [first, first + rows) of `grid` (a slab of it).
RealField sphere_rows(const Grid2D& grid, std::size_t first, std::size_t rows, double radius, double cx, double cy);

/// The steepest surface a rescaled one may be: an RMS slope h'_RMS of at most
/// 100 (the BEM assumes small slopes, ≲ 1; beyond 100 the heights are more than
/// a hundred cells tall per cell and nothing the solvers compute holds).
inline constexpr double max_hprime_rms = 100.0;

/// The h'_RMS of generate_surface(spec, measure, target), from the target PSD
/// alone (every mode's amplitude is fixed, only its phase is random): exact for
/// h'_RMS and h_RMS targets (Parseval), about for Sa (Sa ≈ √(2/π) h_RMS of a
/// Gaussian surface).
double predicted_hprime_rms(const RoughSurfaceSpec& spec, RoughnessMeasure measure, double target);

/// The bounds of a roughness target, one check for every surface made to
/// one (files, `surface generate`, `contact.rough`, Python): h'_RMS in
/// (0, max_hprime_rms], h_RMS and Sa in (0, min(lx, ly)], and the surface's
/// h'_RMS (predicted_hprime_rms) at most max_hprime_rms. InputError naming the
/// measure, its value and the largest allowed on this spectrum.
void check_roughness_target(const RoughSurfaceSpec& spec, RoughnessMeasure measure, double target);
/// What check_roughness_target refuses, without throwing: the problem and what is allowed ("" if none), for a
/// caller that names its own key.
struct RoughnessTargetProblem {
  std::string problem, allowed;
};
RoughnessTargetProblem roughness_target_problem(const RoughSurfaceSpec& spec, RoughnessMeasure measure, double target);

/// generate_surface(spec), then rescaled so that `measure` equals `target`;
/// check_roughness_target first, and the rescaled surface's h'_RMS checked
/// against max_hprime_rms after (an Sa target is only predicted about).
RealField generate_surface(const RoughSurfaceSpec& spec, RoughnessMeasure measure, double target);

/// Spherical cap of radius R centred at (cx, cy), summit up at height 0:
///   h = √(R² − r²) − R  for r ≤ R,   h = −R  for r > R (clipped to the rim),
/// with r the distance to the nearest periodic image of the centre, so the
/// cap may straddle the edges of the periodic cell. InputError if R ≤ 0.
RealField sphere(const Grid2D& grid, double radius, double cx, double cy);

/// h = value everywhere.
RealField plane(const Grid2D& grid, double value);

/// h = slope_x·x + slope_y·y, zero at the origin (x_i = i·dx, y_j = j·dy).
RealField tilted_plane(const Grid2D& grid, double slope_x, double slope_y);

/// a + b point by point; InputError if the grids differ.
RealField add(const RealField& a, const RealField& b);

}  // namespace wearscale::bem
