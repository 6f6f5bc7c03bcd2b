#pragma once
// Internal to the tribometer library: the compliance of an implicit stage's wear.
#include <vector>

#include "wearscale/tribometer/pin_on_disc.hpp"

namespace wearscale::tribometer {

// The wear of an implicit stage as a compliance (bem::AddedCompliance): over
// the stage (length γ) a cell of the pin recedes by γ s p/p_crit (9.23)-(9.24),
// a diagonal term w p, and a column of the averaged disc by the column mean
// of γ (1 − s) p/p_crit scaled by L/L_path, a term c_i mean_j(p) per column
// (its part that differs along the column is iterated on in solve_stage).
struct PinOnDisc::StageCompliance final : bem::AddedCompliance {
  std::vector<double> w;  // per cell [m/Pa]
  std::vector<double> c;  // per column [m/Pa]
  std::size_t ny = 0;

  void add(const RealField& p, double scale, RealField& u) const override {
    const std::size_t nx = c.size();
    for (std::size_t i = 0; i < nx; ++i) {
      const double* pi = p.data() + i * ny;
      double* ui = u.data() + i * ny;
      const double* wi = w.data() + i * ny;
      double column = 0.0;
      for (std::size_t j = 0; j < ny; ++j) column += pi[j];
      const double shift = scale * c[i] * column / static_cast<double>(ny);
      for (std::size_t j = 0; j < ny; ++j) ui[j] += scale * wi[j] * pi[j] + shift;
    }
  }
  double quadratic_form(const RealField& t) const override {
    double sum = 0.0;
    for (std::size_t i = 0; i < c.size(); ++i) {
      const double* ti = t.data() + i * ny;
      const double* wi = w.data() + i * ny;
      double column = 0.0;
      for (std::size_t j = 0; j < ny; ++j) {
        column += ti[j];
        sum += wi[j] * ti[j] * ti[j];
      }
      sum += c[i] * column * column / static_cast<double>(ny);
    }
    return sum;
  }
};

}  // namespace wearscale::tribometer
