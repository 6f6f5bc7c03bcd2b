#pragma once
// Savitzky-Golay smoothing: each point replaced by the value at it of the
// least-squares polynomial of degree `degree` over the `window` points
// centred on it (Savitzky and Golay 1964). Near the ends the window stops at
// the first (last) `window` points and the polynomial fitted there is
// evaluated off-centre (SciPy's mode "interp"), so every point is smoothed
// and a polynomial of degree ≤ `degree` is left unchanged. The fits are GSL's
// linear least squares on the given abscissae (which need not be evenly
// spaced; on an even grid this is the classic convolution filter). The thesis
// reads the maximum of its wear curves off such a smoothed curve (degree 3,
// 11 points, §5.2).
#include <span>
#include <vector>

namespace wearscale {

/// std::invalid_argument unless: x and y have the same length ≥ window, x
/// strictly increasing, window odd, 0 ≤ degree < window.
std::vector<double> savitzky_golay(std::span<const double> x, std::span<const double> y, int window = 11,
                                   int degree = 3);

}  // namespace wearscale
