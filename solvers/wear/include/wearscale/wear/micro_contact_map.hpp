#pragma once
// The micro-contact map the numerical detachment model of ch. 5 works on: the
// grid points in contact, each carrying the junction shear strength σ_j along
// x when the surfaces slide (§5.1). It comes from a BEM rough contact at a
// normalized load p̃_N (5.1) or, for the verification of §5.2, from two
// circular micro-contacts (Fig. 4.3).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "wearscale/core/field.hpp"

namespace wearscale::wear {

struct MicroContactMap {
  Grid2D grid;
  std::vector<std::uint8_t> contact;  ///< 1 where the point is in contact, row-major as the grid
  explicit MicroContactMap(const Grid2D& g) : grid(g), contact(g.size(), 0) {}
  std::size_t points() const;          ///< number of contact points
  double contact_fraction() const;     ///< A/A0
};

/// The points where the normal pressure is positive (§5.1: "all the grid
/// points where the local normal pressure is non-zero are in contact").
MicroContactMap contact_from_pressure(const RealField& pressure);

/// Two circular micro-contacts of diameter d, centres a distance l apart on a
/// line at angle θ to x (Fig. 4.3), centred in the cell: the points whose
/// centre lies within d/2 of either centre. InputError unless the grid is
/// square-celled, d > 0, l ≥ d (disjoint) and both discs fit in the cell.
MicroContactMap two_circles(const Grid2D& grid, double diameter, double distance, double angle);

/// p_N = p̃_N h'_RMS E* / √(2π): the mean pressure of a normalized load   (5.1)
double normal_pressure(double normalized_load, double h_prime_rms, double e_star);

/// The self-affine rough surface of §5.1 (n × n points over L = 1, PSD of
/// Fig. 5.1 with q_r = q_l, rescaled to h'_RMS) pressed on an elastic flat.
struct RoughContactSpec {
  std::size_t n = 512;
  double hurst = 0.8;
  double k_l = 8.0;      ///< q_l L / 2π
  double k_s = 64.0;     ///< q_s L / 2π (n/8 in the thesis)
  double h_prime_rms = 0.1;  ///< scale only: the micro-contacts depend on p̃_N alone (§5.1)
  double poisson = 0.3;
  double tolerance = 1e-10;  ///< Polonsky–Keer tolerance (normal_contact.hpp)
  int max_iterations = 20000;
};

/// Validates a spec (InputError naming the parameter, value and allowed range).
void validate(const RoughContactSpec& spec);

/// The micro-contact maps of one rough surface (one seed) at increasing
/// normalized loads, each BEM solve warm-started from the previous one.
class RoughContactSeries {
 public:
  RoughContactSeries(const RoughContactSpec& spec, std::uint64_t seed);
  ~RoughContactSeries();
  RoughContactSeries(const RoughContactSeries&) = delete;
  RoughContactSeries& operator=(const RoughContactSeries&) = delete;
  /// The contact at p̃_N > 0 (InputError otherwise; NumericalError if the BEM does not converge).
  MicroContactMap at_load(double normalized_load);
  const RealField& surface() const;
  int last_iterations() const { return iterations_; }

 private:
  struct Impl;
  Impl* impl_;
  int iterations_ = 0;
};

}  // namespace wearscale::wear
