// A sphere pressed on a free elastic window with the installed wearscale::bem,
// against Hertz's solution: the approach δ = a²/R within 1e-3, the peak
// pressure within 1 %, the contact radius within one cell (2 % at 64 cells
// over 4a). Also: the shipped data are found from the installed prefix.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "wearscale/bem/hertz.hpp"
#include "wearscale/bem/normal_contact.hpp"
#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/io/shipped_data.hpp"

int main() {
  using namespace wearscale;
  const double radius = 3e-3, load = 1.0, e_star = bem::effective_modulus(73e9, 0.17, 1e30, 0.0);
  const bem::HertzContact hertz{radius, load, e_star};
  const double size = 4.0 * hertz.contact_radius();
  const Grid2D grid = Grid2D::square(64, size);
  bem::NormalContact contact(bem::sphere(grid, radius, size / 2, size / 2), e_star, bem::Boundary::Free);
  const auto r = contact.solve_mean_pressure(load / grid.area());
  const double peak = *std::max_element(contact.pressure().begin(), contact.pressure().end());
  const double a = std::sqrt(r.contact_fraction * grid.area() / M_PI);
  const double e_delta = std::abs(r.interference / hertz.approach() - 1.0);
  const double e_peak = std::abs(peak / hertz.peak_pressure() - 1.0);
  const double e_a = std::abs(a / hertz.contact_radius() - 1.0);
  std::printf("approach %.6e m (Hertz %.6e, rel. error %.2e)\n", r.interference, hertz.approach(), e_delta);
  std::printf("peak pressure %.6e Pa (Hertz %.6e, rel. error %.2e)\n", peak, hertz.peak_pressure(), e_peak);
  std::printf("contact radius %.6e m (Hertz %.6e, rel. error %.2e)\n", a, hertz.contact_radius(), e_a);
  const auto table = materials::shipped_table_path("thesis", "Si");
  std::printf("shipped data: %s\n", table.c_str());
  const bool data_ok = std::filesystem::exists(table);
  return e_delta < 1e-3 && e_peak < 1e-2 && e_a < 2e-2 && data_ok ? 0 : 1;
}
