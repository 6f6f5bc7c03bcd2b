#pragma once
// Roughness amplitude of a surface (thesis §1.1.2): arithmetical mean
// deviation Sa (1.4), RMS of heights h_RMS (1.5) and RMS of slopes h'_RMS (1.6),
// and rescaling a surface to a target value of any of them.
//
// Sa and h_RMS are taken about the mean height ⟨h⟩ (1.3), so they do not
// depend on a constant offset of the surface.
#include <functional>

#include "wearscale/core/field.hpp"

namespace wearscale::bem {

/// ⟨h⟩ over the grid points (1.3).
double mean_height(const RealField& h);

/// Sa = ⟨|h − ⟨h⟩|⟩   (1.4)
double sa(const RealField& h);

/// h_RMS = √⟨(h − ⟨h⟩)²⟩   (1.5)
double h_rms(const RealField& h);

/// h'_RMS = √⟨|∇h|²⟩ (1.6) computed spectrally, for periodic surfaces:
///
///   ⟨|∇h|²⟩ = (1/N²) Σ_q |q|² |ĥ(q)|²,   N = nx·ny,
///
/// Parseval's theorem applied to ∇h, whose DFT is i q ĥ(q) with ĥ the DFT (1.7)
/// in 2D. It is the exact slope of the trigonometric interpolant, i.e. exact
/// for a periodic surface whose spectrum holds no energy at the Nyquist
/// frequency (where the samples do not define the slope; those modes count
/// with |q| = π/dx).
double h_prime_rms(const RealField& h);

/// h'_RMS (1.6) by finite differences, for measured, non-periodic data:
/// forward differences (h(i+1, j) − h(i, j))/dx on the (nx−1)·ny pairs along x
/// and likewise along y (no wrap-around), ⟨|∇h|²⟩ = ⟨(∂x h)²⟩ + ⟨(∂y h)²⟩.
/// Each difference is second-order accurate at its mid-point; a sine of
/// wavenumber q comes out smaller by sin(q dx/2)/(q dx/2).
double h_prime_rms_finite_difference(const RealField& h);

enum class RoughnessMeasure { Sa, HRms, HPrimeRms };

/// The value of `measure` for `h` (HPrimeRms: the spectral h'_RMS).
double roughness(const RealField& h, RoughnessMeasure measure);

/// Name of a measure as used in messages and JSON: "Sa", "h_rms", "h_prime_rms".
const char* name(RoughnessMeasure measure);

/// Multiplies `h` by target / roughness(h, measure), so that the measure equals
/// `target` to round-off (all three measures are homogeneous of degree 1).
/// InputError if the target is not finite and > 0, or if `h` is flat.
void rescale(RealField& h, RoughnessMeasure measure, double target);
/// The same with the current value of the measure from `current` (called after
/// the target is checked): a surface distributed over ranks measures itself whole.
void rescale(RealField& h, RoughnessMeasure measure, double target, const std::function<double()>& current);

}  // namespace wearscale::bem
