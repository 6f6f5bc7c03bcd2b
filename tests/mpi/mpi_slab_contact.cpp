// Run under mpirun by ctest (tests/CMakeLists.txt, label "mpi") at P = 1, 2, 3:
//   mpi_slab_contact operator  the slab-distributed normal block, its
//                              preconditioner and t·Kt equal the serial
//                              HalfSpace's on the same fields (1e-13);
//   mpi_slab_contact surface   each rank's rows of a rough surface made in
//                              slabs equal the rows of the serial surface for
//                              the seed (1e-13), for even and odd sides and
//                              the three roughness measures;
//   mpi_slab_contact solve     the preconditioned and the textbook
//                              Polonsky–Keer solve on slabs take the serial
//                              solve's iterations and give its pressures and
//                              figures to 1e-12 relative.
// Every rank also computes the serial answer (the grids are small) and compares its rows.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "wearscale/bem/normal_contact.hpp"
#include "wearscale/bem/slab_half_space.hpp"
#include "wearscale/bem/slab_surface.hpp"
#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/core/mpi.hpp"

namespace mpi = wearscale::mpi;
using namespace wearscale;
using namespace wearscale::bem;

namespace {
int failures = 0;
double worst = 0.0;  // the largest relative difference a mode measured (printed by rank 0)

void check(bool ok, const std::string& what) {
  if (!ok) {
    std::fprintf(stderr, "rank %d of %d: %s\n", mpi::rank(), mpi::size(), what.c_str());
    ++failures;
  }
}

// max over this rank's rows |slab − whole rows| / max |whole| (over the whole field).
double row_difference(const RealField& slab, const RealField& whole, std::size_t first) {
  double diff = 0.0, scale = 0.0;
  for (const double v : whole) scale = std::max(scale, std::abs(v));
  for (std::size_t k = 0; k < slab.size(); ++k) diff = std::max(diff, std::abs(slab[k] - whole[first * whole.grid().ny + k]));
  const double d = mpi::max(diff) / scale;
  worst = std::max(worst, d);
  return d;
}

RealField rows_of(const RealField& whole, const Grid2D& slab, std::size_t first) {
  RealField r(slab);
  std::copy_n(whole.data() + first * whole.grid().ny, r.size(), r.data());
  return r;
}

double relative(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

void test_operator(const Grid2D& g) {
  const double e_star = 2.5;
  RealField p(g), t(g);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (double& v : p) v = u01(rng);
  for (double& v : t) v = u01(rng) - 0.5;
  HalfSpace serial = HalfSpace::normal(g, e_star);
  auto w = serial.workspace();
  RealField u(g), z(g);
  serial.normal_displacement(p, u, w, 1.5);
  serial.normal_stiffness(t, z, w);
  const double form = serial.normal_form(t, w);

  SlabHalfSpace slab(g, e_star, PlanRigor::Estimate);
  const Grid2D& lg = slab.local_grid();
  RealField u_s(lg), z_s(lg);
  slab.displacement(rows_of(p, lg, slab.first_row()), u_s, 1.5);
  slab.stiffness(rows_of(t, lg, slab.first_row()), z_s);
  const double form_s = slab.form(rows_of(t, lg, slab.first_row()));
  const std::string at = " on " + g.to_string();
  check(row_difference(u_s, u, slab.first_row()) < 1e-13, "u = K p differs from the serial body's" + at);
  check(row_difference(z_s, z, slab.first_row()) < 1e-13, "z = S t differs from the serial body's" + at);
  check(relative(form_s, form) < 1e-13, "t·Kt differs from the serial body's" + at);
  check(relative(slab.self_compliance(), serial.self_compliance()) < 1e-13, "self compliance differs" + at);
  check(relative(slab.stiffness_diagonal(), serial.normal_stiffness_diagonal()) < 1e-13,
        "S at offset 0 differs" + at);
  const long long rows = mpi::sum(static_cast<long long>(slab.rows()));
  check(rows == static_cast<long long>(g.nx), "the slabs do not cover the grid" + at);
}

void test_surface(const Grid2D& g, std::uint64_t seed) {
  RoughSurfaceSpec spec;
  spec.grid = g;
  spec.hurst = 0.7;
  spec.k_l = 2.0;
  spec.k_r = 4.0;
  spec.k_s = static_cast<double>(std::min(g.nx, g.ny) / 2);
  spec.seed = seed;
  SlabFFT fft(g.nx, g.ny, PlanRigor::Estimate);
  const std::string at = " on " + g.to_string() + ", seed " + std::to_string(seed);
  check(row_difference(generate_surface_slab(spec, fft), generate_surface(spec), fft.first_row()) < 1e-13,
        "the slab surface differs from the serial one" + at);
  for (const auto measure : {RoughnessMeasure::HPrimeRms, RoughnessMeasure::HRms, RoughnessMeasure::Sa}) {
    const RealField whole = generate_surface(spec, measure, 0.3);
    const RealField slab = generate_surface_slab(spec, measure, 0.3, fft);
    check(row_difference(slab, whole, fft.first_row()) < 1e-13,
          std::string("the rescaled slab surface differs (") + name(measure) + ")" + at);
    check(relative(roughness_slab(slab, g, measure, fft), 0.3) < 1e-13,
          std::string("the slab surface's ") + name(measure) + " is not the target" + at);
  }
}

void test_solve(std::size_t n, ContactMethod method) {
  // The case on a smaller grid: H = 0.8, k_l = k_r = 4, k_s = 64, h'_RMS = 1, p̄ = 0.03 E*.
  RoughSurfaceSpec spec;
  spec.grid = Grid2D::square(n, 1.0);
  spec.hurst = 0.8;
  spec.k_l = spec.k_r = 4.0;
  spec.k_s = std::min(64.0, static_cast<double>(n / 2));
  spec.seed = 1;
  const RealField h = generate_surface(spec, RoughnessMeasure::HPrimeRms, 1.0);
  ContactOptions options;
  options.tolerance = 1e-10;
  options.method = method;
  NormalContact serial(h, 1.0);
  const ContactResult r = serial.solve_mean_pressure(0.03, options);

  auto body = std::make_unique<SlabHalfSpace>(spec.grid, 1.0, PlanRigor::Estimate);
  const std::size_t first = body->first_row();
  const Grid2D lg = body->local_grid();
  NormalContact slab(std::move(body), rows_of(h, lg, first), 1.0);
  const ContactResult s = slab.solve_mean_pressure(0.03, options);
  const std::string at = std::string(method == ContactMethod::PolonskyKeer ? " (Polonsky–Keer)" : " (preconditioned)") +
                         " on " + spec.grid.to_string();
  check(s.iterations == r.iterations,
        "iterations " + std::to_string(s.iterations) + " against serial " + std::to_string(r.iterations) + at);
  check(row_difference(slab.pressure(), serial.pressure(), first) < 1e-12, "pressures differ" + at);
  check(row_difference(slab.displacement(), serial.displacement(), first) < 1e-12, "displacements differ" + at);
  check(relative(s.mean_pressure, r.mean_pressure) < 1e-12, "mean pressure differs" + at);
  check(s.contact_fraction == r.contact_fraction, "contact fraction differs" + at);
  check(relative(s.interference, r.interference) < 1e-12, "interference differs" + at);
  check(relative(s.elastic_energy, r.elastic_energy) < 1e-12, "elastic energy differs" + at);
  check(s.error < 1e-10 && r.iterations > 5, "not converged, or trivially" + at);
  if (mpi::is_root())
    std::printf("%s: %d iterations (serial %d), |Δp|/max p = %.2e, Δδ/δ = %.2e\n", at.c_str(), s.iterations,
                r.iterations, row_difference(slab.pressure(), serial.pressure(), first),
                relative(s.interference, r.interference));
  else
    (void)row_difference(slab.pressure(), serial.pressure(), first);  // the same collective calls as rank 0
}
}  // namespace

int main(int argc, char** argv) {
  mpi::Session session(argc, argv);
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "operator") {
    test_operator(Grid2D::square(256, 1.0));
    test_operator(Grid2D(45, 32, 2.0, 1.5));  // odd rows, rectangular
    test_operator(Grid2D(64, 33, 1.0, 0.5));  // odd columns
  } else if (mode == "surface") {
    test_surface(Grid2D::square(256, 1.0), 1);
    test_surface(Grid2D(45, 32, 1.0, 1.0), 3);
    test_surface(Grid2D(64, 33, 1.0, 1.0), 4);
  } else if (mode == "solve") {
    test_solve(256, ContactMethod::PreconditionedCG);
    test_solve(128, ContactMethod::PolonskyKeer);
  } else {
    std::fprintf(stderr, "usage: mpi_slab_contact operator | surface | solve\n");
    return 2;
  }
  const long long failed = mpi::sum(static_cast<long long>(failures));
  if (mpi::is_root())
    std::printf("%s at %d ranks: %s (largest field difference %.2e)\n", mode.c_str(), mpi::size(),
                failed == 0 ? "ok" : "FAILED", worst);
  return failed == 0 ? 0 : 1;
}
