#pragma once
// Averages of the friction coefficient over sliding distance. Every average
// is weighted by distance: it is a difference of the integral
// I(s) = ∫₀ˢ μ ds' that the integrators carry with the state (the explicit
// stepping sums μ ds, the adaptive one integrates it under error control),
// read between samples by linear interpolation.
#include <string>
#include <vector>

namespace wearscale::tribometer {

class FrictionAverage {
 public:
  /// Samples at non-decreasing distances `s` with I(s) in `integral`;
  /// InputError if the sizes differ, there are none, or s decreases.
  FrictionAverage(std::vector<double> s, std::vector<double> integral);

  /// I(s), linear between samples, clamped to the sampled range.
  double integral_at(double s) const;
  /// Mean of μ over [a, b] (within the sampled range): (I(b) − I(a)) / (b − a).
  double mean(double a, double b) const;
  /// At every sample, the mean over the window of `length` centred on it,
  /// shrunk to the sampled range at the ends (the moving average of Fig. 9.23).
  std::vector<double> centred_moving_average(double length) const;

  double first() const { return s_.front(); }
  double last() const { return s_.back(); }

 private:
  std::vector<double> s_, integral_;
};

/// The stretch of sliding that "final" and "initial" friction refer to: one
/// whole period of the rotating tilt when there is one (the whole run if it is
/// shorter), else the last (first) 5 % of the distance.
struct FrictionWindow {
  double from = 0.0, to = 0.0;
  std::string description;  ///< for the report: "the last whole tilt period (0.05 m)", ...
};
FrictionWindow final_window(double start, double end, double tilt_period);
FrictionWindow initial_window(double start, double end, double tilt_period);

}  // namespace wearscale::tribometer
