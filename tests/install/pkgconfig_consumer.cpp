// A program built with nothing but `c++ $(pkg-config --cflags --libs wearscale)`
// (tests/install/install_test.cmake): it reads its Hertz case from TOML text
// through wearscale's Config (toml++, a shared library of its own), asks how
// many ranks it runs on (core calls MPI in an MPI build) and solves the sphere
// on a free 32² window with wearscale::bem: the approach δ = a²/R (1.12)
// within 1e-3 of Hertz's. Exit 0 if so, 1 if not.
#include <cmath>
#include <cstdio>

#include "wearscale/bem/hertz.hpp"
#include "wearscale/bem/normal_contact.hpp"
#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/core/version.hpp"
#include "wearscale/io/config.hpp"

int main() {
  using namespace wearscale;
  const Config c = Config::from_string("radius = \"3 mm\"\nload = \"1 N\"\ne_star = \"75 GPa\"\n", "pkg-config case");
  const double radius = c.number("radius", Range::positive(), units::length);
  const double load = c.number("load", Range::positive(), units::force);
  const double e_star = c.number("e_star", Range::positive(), units::pressure);
  const bem::HertzContact hertz{radius, load, e_star};
  const double size = 4.0 * hertz.contact_radius();
  const Grid2D grid = Grid2D::square(32, size);
  bem::NormalContact contact(bem::sphere(grid, radius, size / 2, size / 2), e_star, bem::Boundary::Free);
  const double error = std::abs(contact.solve_mean_pressure(load / grid.area()).interference / hertz.approach() - 1.0);
  std::printf("wearscale %s, %d rank(s): approach rel. error %.2e against Hertz (1.12)\n", version().c_str(),
              mpi::size(), error);
  return error < 1e-3 ? 0 : 1;
}
