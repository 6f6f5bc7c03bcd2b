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
//                              figures to 1e-12 relative;
//   mpi_slab_contact traction  the slab-distributed Boussinesq–Cerruti tensor
//                              (u = F p, all components, and the blocks of
//                              t·Ft) equals the serial HalfSpace's (1e-13);
//   mpi_slab_contact coulomb   a Coulomb (tresca: a Tresca) frictional solve
//                              on slabs takes the serial solve's iterations and
//                              gives its tractions, stick/slip map and figures
//                              to 1e-12 relative (rank 0 solves the serial case);
//   mpi_slab_contact free      the free (zero-padded) normal block on slabs,
//                              its preconditioner and t·Kt equal the serial
//                              free HalfSpace's (1e-13), on even, odd and
//                              rectangular grids; a Hertz solve on a free
//                              window takes the serial iterations and gives
//                              its pressures, approach δ and figures to 1e-12,
//                              and a contact reaching the window's edge is
//                              refused on every rank, as serially;
//   mpi_slab_contact stress    the stresses below tractions (six components at
//                              the surface and two depths) from each rank's
//                              rows equal the serial SubsurfaceStress's (1e-13);
//   mpi_slab_contact crack     the micro-contacts' labels of each rank's rows
//                              equal the whole map's (4- and 8-connected), and
//                              (4.25) per micro-contact from the slabs equals
//                              the whole map's check to the bit (edge extremes
//                              and flags), for contacts that cross the slabs'
//                              edges and the cell's, along four directions;
//   mpi_slab_contact stop      a stop asked on the last rank alone ends the
//                              normal and the frictional solve on every rank at
//                              the same iteration (Interrupted): none waits.
// Every rank also computes the serial answer (the grids are small) and compares its rows
// (but for the frictional solves: there rank 0 alone does).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "wearscale/bem/crack_initiation.hpp"
#include "wearscale/bem/frictional_contact.hpp"
#include "wearscale/bem/normal_contact.hpp"
#include "wearscale/bem/principal_stresses.hpp"
#include "wearscale/bem/slab_clusters.hpp"
#include "wearscale/bem/slab_crack_initiation.hpp"
#include "wearscale/bem/slab_free_half_space.hpp"
#include "wearscale/bem/slab_half_space.hpp"
#include "wearscale/bem/slab_subsurface_stress.hpp"
#include "wearscale/bem/slab_surface.hpp"
#include "wearscale/bem/subsurface_stress.hpp"
#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/core/errors.hpp"
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

// A slab body's u = K p, z = S t, t·Kt, self compliance and S(0) against the
// serial HalfSpace of the same boundary, on random fields drawn from `seed`.
template <class SlabBody>
void compare_with_serial_body(SlabBody& slab, const Grid2D& g, Boundary boundary, unsigned seed) {
  const double e_star = 2.5;
  RealField p(g), t(g);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (double& v : p) v = u01(rng);
  for (double& v : t) v = u01(rng) - 0.5;
  HalfSpace serial = HalfSpace::normal(g, e_star, boundary);
  auto w = serial.workspace();
  RealField u(g), z(g);
  serial.normal_displacement(p, u, w, 1.5);
  serial.normal_stiffness(t, z, w);
  const double form = serial.normal_form(t, w);

  const Grid2D& lg = slab.local_grid();
  const std::size_t first = slab.first_row();
  RealField u_s(lg), z_s(lg);
  slab.displacement(rows_of(p, lg, first), u_s, 1.5);
  slab.stiffness(rows_of(t, lg, first), z_s);
  const double form_s = slab.form(rows_of(t, lg, first));
  // The two-level stiffness (S itself on a free window or an odd grid), against the serial body's.
  HalfSpaceNormal whole(g, e_star, boundary);
  RealField m(g), m_s(lg);
  whole.two_level_stiffness(t, m);
  slab.two_level_stiffness(rows_of(t, lg, first), m_s);
  const std::string at = std::string(boundary == Boundary::Free ? " (free)" : "") + " on " + g.to_string();
  check(row_difference(m_s, m, first) < 1e-13, "z = M t (two-level) differs from the serial body's" + at);
  check(slab.boundary() == boundary, "the body's boundary differs" + at);
  check(row_difference(u_s, u, first) < 1e-13, "u = K p differs from the serial body's" + at);
  check(row_difference(z_s, z, first) < 1e-13, "z = S t differs from the serial body's" + at);
  check(relative(form_s, form) < 1e-13, "t·Kt differs from the serial body's" + at);
  check(relative(slab.self_compliance(), serial.self_compliance()) < 1e-13, "self compliance differs" + at);
  check(relative(slab.stiffness_diagonal(), serial.normal_stiffness_diagonal()) < 1e-13,
        "S at offset 0 differs" + at);
  check(mpi::sum(static_cast<long long>(slab.rows())) == static_cast<long long>(g.nx),
        "the slabs do not cover the grid" + at);
}

void test_operator(const Grid2D& g) {
  SlabHalfSpace slab(g, 2.5, PlanRigor::Estimate);
  compare_with_serial_body(slab, g, Boundary::Periodic, 7);
}

void test_surface(const Grid2D& g, std::uint64_t seed) {
  // {grid, H, k_l, k_r, k_s, seed}: the spectrum of Fig. 1.3.
  const RoughSurfaceSpec spec{g, 0.7, 2.0, 4.0, static_cast<double>(std::min(g.nx, g.ny) / 2), seed};
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
  const RoughSurfaceSpec spec{Grid2D::square(n, 1.0), 0.8, 4.0, 4.0, std::min(64.0, static_cast<double>(n / 2)), 1};
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
  const std::string at = std::string(method == ContactMethod::PolonskyKeer ? " (Polonsky–Keer)"
                                     : method == ContactMethod::TwoLevelCG ? " (two-level)"
                                                                            : " (preconditioned)") +
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
void test_free_operator(const Grid2D& g) {
  SlabFreeHalfSpace slab(g, 2.5, PlanRigor::Estimate);
  compare_with_serial_body(slab, g, Boundary::Free, 11);
  // The contact's rows are where a rough surface made in slabs puts them.
  SlabFFT surface(g.nx, g.ny, PlanRigor::Estimate);
  check(surface.first_row() == slab.first_row() && surface.rows() == slab.rows(),
        "the rows differ from the slabs of the contact's own grid (free) on " + g.to_string());
}

void test_free_solve(std::size_t n) {
  // A sphere on a free window four Hertz radii wide (the Python hertz_check's case).
  const double e_star = 1.0, radius = 1.0, a = 0.1, size = 4.0 * a;
  const double load = 4.0 * e_star * a * a * a / (3.0 * radius);  // Hertz: a³ = 3 P R / (4 E*)
  const Grid2D g = Grid2D::square(n, size);
  const RealField h = sphere(g, radius, size / 2, size / 2);
  ContactOptions options;
  options.tolerance = 1e-10;
  NormalContact serial(h, e_star, Boundary::Free);
  const ContactResult r = serial.solve_mean_pressure(load / g.area(), options);

  auto body = std::make_unique<SlabFreeHalfSpace>(g, e_star, PlanRigor::Estimate);
  const std::size_t first = body->first_row();
  const Grid2D lg = body->local_grid();
  check(row_difference(sphere_rows(g, first, lg.nx, radius, size / 2, size / 2), h, first) == 0.0,
        "the sphere's rows differ from the serial sphere's");
  NormalContact slab(std::move(body), rows_of(h, lg, first), e_star);
  const ContactResult s = slab.solve_mean_pressure(load / g.area(), options);
  const std::string at = " (free, Hertz) on " + g.to_string();
  check(s.iterations == r.iterations,
        "iterations " + std::to_string(s.iterations) + " against serial " + std::to_string(r.iterations) + at);
  check(row_difference(slab.pressure(), serial.pressure(), first) < 1e-12, "pressures differ" + at);
  check(row_difference(slab.displacement(), serial.displacement(), first) < 1e-12, "displacements differ" + at);
  check(s.contact_fraction == r.contact_fraction, "contact fraction differs" + at);
  check(relative(s.interference, r.interference) < 1e-12, "approach δ differs" + at);
  check(relative(s.elastic_energy, r.elastic_energy) < 1e-12, "elastic energy differs" + at);
  // Not an image-corrected δ: the free window's approach is Hertz's a²/R to the discretisation.
  check(relative(s.interference, a * a / radius) < 0.02, "δ is not Hertz's a²/R to 2 %" + at);

  // Ten times the load: the contact (a × 10^⅓ = 0.215 against a half window of 0.2) reaches the edge.
  bool serial_refused = false, slab_refused = false;
  try {
    serial.solve_mean_pressure(10.0 * load / g.area(), options);
  } catch (const InputError&) {
    serial_refused = true;
  }
  try {
    slab.solve_mean_pressure(10.0 * load / g.area(), options);
  } catch (const InputError&) {
    slab_refused = true;
  }
  check(serial_refused, "the serial solve reaching the window's edge was not refused" + at);
  check(slab_refused, "the slab solve reaching the window's edge was not refused on this rank" + at);
  if (mpi::is_root())
    std::printf("%s: %d iterations (serial %d), δ/(a²/R) = %.4f\n", at.c_str(), s.iterations, r.iterations,
                s.interference / (a * a / radius));
}

void test_stress(const Grid2D& g) {
  VectorField t(g);
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (double& v : t.z) v = u01(rng);
  for (double& v : t.x) v = 0.3 * (u01(rng) - 0.5);
  for (double& v : t.y) v = 0.2 * (u01(rng) - 0.5);
  SubsurfaceStress serial(g, 0.3);
  serial.set_traction(t);
  SlabFFT fft(g.nx, g.ny, PlanRigor::Estimate);
  SlabSubsurfaceStress slab(g, 0.3, fft);
  const Grid2D& lg = slab.local_grid();
  const std::size_t first = fft.first_row();
  VectorField rows(lg);
  rows.x = rows_of(t.x, lg, first);
  rows.y = rows_of(t.y, lg, first);
  rows.z = rows_of(t.z, lg, first);
  slab.set_traction(rows);
  StressField whole(g), part(lg);
  for (const double depth : {0.0, 0.5 * g.dx(), 4.0 * g.dx()}) {
    serial.stress(depth, whole);
    slab.stress(depth, part);
    const std::string at = " at depth " + std::to_string(depth) + " on " + g.to_string();
    check(row_difference(part.xx, whole.xx, first) < 1e-13, "σ_xx differs" + at);
    check(row_difference(part.yy, whole.yy, first) < 1e-13, "σ_yy differs" + at);
    check(row_difference(part.zz, whole.zz, first) < 1e-13, "σ_zz differs" + at);
    check(row_difference(part.xy, whole.xy, first) < 1e-13, "σ_xy differs" + at);
    check(row_difference(part.xz, whole.xz, first) < 1e-13, "σ_xz differs" + at);
    check(row_difference(part.yz, whole.yz, first) < 1e-13, "σ_yz differs" + at);
  }
}

// A sliding rough contact (a fifth of the cell) whose micro-contacts cross the
// slabs' edges, and with `band` one more around the cell along y, across its
// edge along x (its last two rows and first two): each rank's labels and the
// (4.25) checks from the slabs against the whole map's.
void test_crack(const Grid2D& g, Connectivity connectivity, bool band) {
  const RoughSurfaceSpec spec{g, 0.8, 2.0, 2.0, static_cast<double>(std::min(g.nx, g.ny) / 4), 5};
  const RealField h = generate_surface(spec, RoughnessMeasure::HPrimeRms, 1.0);
  std::vector<double> sorted(h.begin(), h.end());
  std::sort(sorted.begin(), sorted.end());
  const double cut = sorted[static_cast<std::size_t>(0.8 * static_cast<double>(sorted.size()))];
  VectorField t(g);
  for (std::size_t k = 0; k < g.size(); ++k) {
    const std::size_t i = k / g.ny;
    t.z[k] = std::max(h[k] - cut, 0.0) + (band && (i < 2 || i + 2 >= g.nx) ? 0.5 * (sorted.back() - cut) : 0.0);
    t.x[k] = 0.5 * t.z[k];
  }
  SubsurfaceStress solid(g, 0.3);
  solid.set_traction(t);
  StressField stress(g);
  solid.stress(0.0, stress);
  PrincipalStresses whole(g);
  principal_stresses(stress, whole);
  // Rank 0's fields on every rank: FFTW may take other codelets in another
  // process (the arrays' alignment), which moves the last bits.
  for (RealField* f : {&t.z, &whole.first, &whole.third}) mpi::broadcast(f->values());
  const ContactMap map = find_clusters(t.z, connectivity);

  const RowRange mine = SlabFFT::layout(g.nx, g.ny);
  const Grid2D lg(mine.rows, g.ny, g.dx() * static_cast<double>(mine.rows), g.ly);
  const SlabContactMap slab = label_clusters_slab(rows_of(t.z, lg, mine.first), mine.first, g, connectivity);
  const std::string at = " on " + g.to_string() + (connectivity == Connectivity::Eight ? ", 8-connected" : "");
  check(slab.count == map.clusters.size(), "cluster counts differ" + at);
  check(map.clusters.size() >= 3, "too few micro-contacts to test" + at);
  bool same_labels = slab.label.size() == lg.size();
  for (std::size_t k = 0; same_labels && k < slab.label.size(); ++k)
    same_labels = slab.label[k] == map.label[mine.first * g.ny + k];
  check(same_labels, "the labels of this rank's rows differ from the whole map's" + at);
  bool spans = false;
  for (const auto& c : map.clusters) spans = spans || c.spans_cell;
  check(!band || spans, "no micro-contact wraps around the cell" + at);

  PrincipalStresses part(lg);
  part.first = rows_of(whole.first, lg, mine.first);
  part.third = rows_of(whole.third, lg, mine.first);
  for (const auto& [dx, dy] : {std::pair{1.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}, {-1.0, 0.3}}) {
    // σ_m in the middle of the micro-contacts' edge extremes, so that some initiate and some do not.
    std::vector<EdgeCrackCheck> serial = crack_initiation(map, whole, dx, dy, 1.0);
    std::vector<double> both;
    for (const auto& c : serial)
      if (std::isfinite(c.trailing_tension) && std::isfinite(c.leading_compression))
        both.push_back(std::min(c.trailing_tension, -c.leading_compression));
    std::sort(both.begin(), both.end());
    const std::size_t half = both.size() / 2;
    const double sigma_m = both.size() < 2 ? 1.0 : std::max(0.5 * (both[half - 1] + both[half]), 1e-9);
    serial = crack_initiation(map, whole, dx, dy, sigma_m);
    const std::vector<EdgeCrackCheck> ranks = crack_initiation_slab(slab, part, mine.first, g, dx, dy, sigma_m);
    const std::string along = at + " along (" + std::to_string(dx) + ", " + std::to_string(dy) + ")";
    check(ranks.size() == serial.size(), "the checks' counts differ" + along);
    std::size_t initiating = 0, same = 0;
    for (std::size_t c = 0; c < std::min(ranks.size(), serial.size()); ++c) {
      initiating += serial[c].initiates() ? 1 : 0;
      same += ranks[c].trailing_tension == serial[c].trailing_tension &&
                      ranks[c].leading_compression == serial[c].leading_compression &&
                      ranks[c].trailing == serial[c].trailing && ranks[c].leading == serial[c].leading
                  ? 1
                  : 0;
    }
    check(same == serial.size(), std::to_string(serial.size() - same) + " checks differ from the whole map's" + along);
    check(initiating > 0 && initiating < serial.size(), "every micro-contact or none initiates: a weak test" + along);
  }
}

VectorField vector_rows_of(const VectorField& whole, const Grid2D& slab, std::size_t first) {
  VectorField r(slab);
  r.x = rows_of(whole.x, slab, first);
  r.y = rows_of(whole.y, slab, first);
  r.z = rows_of(whole.z, slab, first);
  return r;
}

void test_traction(const Grid2D& g) {
  const double young = 2.5, poisson = 0.3;
  VectorField p(g);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u01(-0.5, 1.0);
  for (RealField* f : {&p.x, &p.y, &p.z})
    for (double& v : *f) v = u01(rng);
  HalfSpace serial(g, young, poisson, Boundary::Periodic, Response::Full);
  auto w = serial.workspace();
  VectorField u(g);
  serial.displacement(p, u, w);
  const HalfSpace::BlockForm form = serial.form(p, w);

  SlabHalfSpace slab(g, young, poisson, PlanRigor::Estimate);
  const Grid2D& lg = slab.local_grid();
  const std::size_t first = slab.first_row();
  VectorField u_s(lg);
  const VectorField p_s = vector_rows_of(p, lg, first);
  slab.vector_displacement(p_s, u_s);
  const HalfSpace::BlockForm form_s = slab.block_form(p_s);
  RealField uz_n(lg);
  slab.displacement(p_s.z, uz_n, 1.0);  // the normal block of the full tensor
  const std::string at = " on " + g.to_string();
  check(row_difference(u_s.x, u.x, first) < 1e-13, "u_x = F p differs from the serial body's" + at);
  check(row_difference(u_s.y, u.y, first) < 1e-13, "u_y = F p differs from the serial body's" + at);
  check(row_difference(u_s.z, u.z, first) < 1e-13, "u_z = F p differs from the serial body's" + at);
  RealField uz(g);
  serial.normal_displacement(p.z, uz, w);
  check(row_difference(uz_n, uz, first) < 1e-13, "the normal block differs from the serial body's" + at);
  const double scale = std::max({std::abs(form.nn), std::abs(form.tt), std::abs(form.nt)});
  check(std::abs(form_s.nn - form.nn) < 1e-13 * scale && std::abs(form_s.tt - form.tt) < 1e-13 * scale &&
            std::abs(form_s.nt - form.nt) < 1e-13 * scale,
        "the blocks of t·Ft differ from the serial body's" + at);
  check(relative(slab.self_compliance(), serial.self_compliance()) < 1e-13, "self compliance differs" + at);
  check(relative(slab.stiffness_diagonal(), serial.normal_stiffness_diagonal()) < 1e-13,
        "S at offset 0 differs" + at);
}

// Every rank's rows of a slab field, whole on rank 0 (empty elsewhere).
RealField whole_of(const RealField& slab, const Grid2D& g) {
  RealField whole(mpi::is_root() ? g : Grid2D(0, g.ny, 1.0, g.ly));
  mpi::gather(slab.values(), whole.values());
  return whole;
}

// max |a − b| / max |b| over the whole field.
double difference(const RealField& a, const RealField& b) {
  double diff = 0.0, scale = 0.0;
  for (std::size_t k = 0; k < b.size(); ++k) {
    scale = std::max(scale, std::abs(b[k]));
    diff = std::max(diff, std::abs(a[k] - b[k]));
  }
  const double d = scale > 0.0 ? diff / scale : diff;
  worst = std::max(worst, d);
  return d;
}

// A rough sphere (paraboloid of radius R on a rough surface) pressed and
// sheared along x, ν = 0.3 (normal and tangential coupled). The slab solve
// runs on every rank; rank 0 gathers its fields and alone solves the serial
// case to compare (P serial solves side by side would only slow the test).
void test_friction(std::size_t n, FrictionLaw law, double tangential_share) {
  const Grid2D g = Grid2D::square(n, 1.0);
  const RoughSurfaceSpec spec{g, 0.8, 8.0, 8.0, static_cast<double>(n / 4), 1};
  RealField h = generate_surface(spec, RoughnessMeasure::HRms, 2e-4);
  const double radius = 10.0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      const double x = g.x(i) - 0.5, y = g.y(j) - 0.5;
      h(i, j) -= (x * x + y * y) / (2.0 * radius);
    }
  const double young = 1.0, poisson = 0.3, p_n = 1.5e-4;
  auto body = std::make_unique<SlabHalfSpace>(g, young, poisson, PlanRigor::Estimate);
  const std::size_t first = body->first_row();
  const Grid2D lg = body->local_grid();
  FrictionalContact slab(std::move(body), rows_of(h, lg, first), law);
  // Coulomb: a share of μ p_N; Tresca: a share of σ_m,T times Hertz's contact area πa²/L² (a ≈ 0.1 here).
  const double capacity = law.kind() == FrictionLaw::Kind::Coulomb ? law.parameter() * p_n
                                                                    : law.parameter() * std::numbers::pi * 0.01;
  const MeanTraction load{p_n, tangential_share * capacity, 0.0};
  FrictionalOptions options;
  options.tolerance = 1e-10;
  const FrictionalResult s = slab.solve(load, options);
  const VectorField& ps = slab.traction();
  const RealField px = whole_of(ps.x, g), py = whole_of(ps.y, g), pz = whole_of(ps.z, g);
  const RealField ux = whole_of(slab.displacement().x, g), uz = whole_of(slab.displacement().z, g);
  const RealField map = whole_of(slab.stick_slip_map(), g);
  if (!mpi::is_root()) return;

  FrictionalContact serial(h, young, poisson, law);
  const FrictionalResult r = serial.solve(load, options);
  const std::string at = " (" + law.to_string() + ") on " + g.to_string();
  check(s.iterations == r.iterations,
        "iterations " + std::to_string(s.iterations) + " against serial " + std::to_string(r.iterations) + at);
  check(s.bound_updates == r.bound_updates, "friction bound updates differ" + at);
  const double dz = difference(pz, serial.traction().z), dx = difference(px, serial.traction().x),
               dy = difference(py, serial.traction().y);
  check(dz < 1e-12, "p_N differs" + at);
  check(dx < 1e-12, "p_x differs" + at);
  check(dy < 1e-12, "p_y differs" + at);
  check(difference(uz, serial.displacement().z) < 1e-12, "u_z differs" + at);
  check(difference(ux, serial.displacement().x) < 1e-12, "u_x differs" + at);
  check(difference(map, serial.stick_slip_map()) == 0.0, "stick/slip maps differ" + at);
  check(relative(s.mean_traction.normal, r.mean_traction.normal) < 1e-12, "⟨p_N⟩ differs" + at);
  check(relative(s.mean_traction.x, r.mean_traction.x) < 1e-12, "⟨p_x⟩ differs" + at);
  check(s.contact_fraction == r.contact_fraction, "contact fraction differs" + at);
  check(s.stick_fraction == r.stick_fraction, "stick fraction differs" + at);
  check(s.slip_fraction == r.slip_fraction, "slip fraction differs" + at);
  check(s.unsettled_points == r.unsettled_points, "unsettled points differ" + at);
  check(relative(s.interference, r.interference) < 1e-12, "interference differs" + at);
  check(relative(s.tangential_displacement_x, r.tangential_displacement_x) < 1e-12, "δ_x differs" + at);
  check(relative(s.elastic_energy, r.elastic_energy) < 1e-12, "elastic energy differs" + at);
  check(relative(s.frictional_force_ratio, r.frictional_force_ratio) < 1e-12, "‖⟨p_T⟩‖/⟨p_N⟩ differs" + at);
  check(s.error < 1e-10 && std::abs(s.error - r.error) < 1e-12, "ε differs or not converged" + at);
  check(r.iterations > 5 && r.stick_fraction > 0.0 && r.slip_fraction > 0.0, "not partial slip, or trivial" + at);
  std::printf("%s: %d iterations (serial %d), %d bound updates, stick %.4f slip %.4f, |Δp|/max p = %.2e %.2e %.2e, "
              "Δδ/δ = %.2e, ΔE/E = %.2e\n",
              at.c_str(), s.iterations, r.iterations, s.bound_updates, s.stick_fraction, s.slip_fraction, dz, dx, dy,
              relative(s.interference, r.interference), relative(s.elastic_energy, r.elastic_energy));
}

// Solves with a stop that the last rank alone asks for at its 4th iteration:
// every rank must end with Interrupted after asking 4 times (the answers go
// through the iteration's own sums), not wait for the others.
template <class Solve>
void expect_stop_everywhere(const std::string& what, Solve solve) {
  int asked = 0;
  const auto stop = [&asked] { return ++asked >= 4 && mpi::rank() == mpi::size() - 1; };
  bool interrupted = false;
  try {
    solve(stop);
  } catch (const Interrupted&) {
    interrupted = true;
  }
  check(interrupted, what + ": the solve did not stop");
  check(mpi::max(static_cast<double>(asked)) == 4.0 && -mpi::max(-static_cast<double>(asked)) == 4.0,
        what + ": the ranks stopped at different iterations (asked " + std::to_string(asked) + " times here)");
}

void test_stop(std::size_t n) {
  const Grid2D g = Grid2D::square(n, 1.0);
  const RoughSurfaceSpec spec{g, 0.8, 4.0, 4.0, static_cast<double>(n / 4), 1};
  const RealField h = generate_surface(spec, RoughnessMeasure::HPrimeRms, 1.0);
  expect_stop_everywhere("normal contact", [&](auto stop) {
    auto body = std::make_unique<SlabHalfSpace>(g, 1.0, PlanRigor::Estimate);
    const std::size_t first = body->first_row();
    const Grid2D lg = body->local_grid();
    NormalContact slab(std::move(body), rows_of(h, lg, first), 1.0);
    ContactOptions options;
    options.stop = stop;
    slab.solve_mean_pressure(0.03, options);
  });
  expect_stop_everywhere("frictional contact", [&](auto stop) {
    auto body = std::make_unique<SlabHalfSpace>(g, 1.0, 0.3, PlanRigor::Estimate);
    const std::size_t first = body->first_row();
    const Grid2D lg = body->local_grid();
    FrictionalContact slab(std::move(body), rows_of(h, lg, first), FrictionLaw::coulomb(0.5));
    FrictionalOptions options;
    options.stop = stop;
    slab.solve(MeanTraction{0.03, 0.005, 0.0}, options);
  });
}
}  // namespace

int main(int argc, char** argv) {
  mpi::Session session(argc, argv);
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "operator") {
    test_operator(Grid2D::square(256, 1.0));
    test_operator(Grid2D(45, 32, 2.0, 1.5));  // odd rows, rectangular
    test_operator(Grid2D(64, 33, 1.0, 0.5));  // odd columns
    test_operator(Grid2D(20, 24, 1.0, 1.2));  // FFTW's slabs start on odd rows at P = 3 (7, 7, 6)
    test_operator(Grid2D(6, 8, 1.0, 1.0));    // and at P = 2 (3, 3); two rows a rank at P = 3
  } else if (mode == "surface") {
    test_surface(Grid2D::square(256, 1.0), 1);
    test_surface(Grid2D(45, 32, 1.0, 1.0), 3);
    test_surface(Grid2D(64, 33, 1.0, 1.0), 4);
  } else if (mode == "solve") {
    test_solve(256, ContactMethod::PreconditionedCG);
    test_solve(128, ContactMethod::PolonskyKeer);
    test_solve(256, ContactMethod::TwoLevelCG);
    test_solve(90, ContactMethod::TwoLevelCG);  // slabs of 45 rows at P = 2: moved to even rows
  } else if (mode == "traction") {
    test_traction(Grid2D::square(64, 1.0));
    test_traction(Grid2D(45, 32, 2.0, 1.5));  // odd rows, rectangular
    test_traction(Grid2D(64, 33, 1.0, 0.5));  // odd columns
  } else if (mode == "coulomb") {
    test_friction(64, FrictionLaw::coulomb(0.5), 0.5);
  } else if (mode == "tresca") {
    test_friction(64, FrictionLaw::tresca(2e-3), 0.3);
  } else if (mode == "free") {
    test_free_operator(Grid2D::square(64, 1.0));
    test_free_operator(Grid2D(45, 32, 2.0, 1.5));  // odd rows, rectangular
    test_free_operator(Grid2D(20, 33, 1.0, 0.5));  // odd columns, few rows
    test_free_solve(64);
  } else if (mode == "stress") {
    test_stress(Grid2D::square(64, 1.0));
    test_stress(Grid2D(45, 32, 2.0, 1.5));  // odd rows, rectangular
    test_stress(Grid2D(64, 33, 1.0, 0.5));  // odd columns
  } else if (mode == "crack") {
    test_crack(Grid2D::square(64, 1.0), Connectivity::Four, false);
    test_crack(Grid2D(45, 32, 2.0, 1.5), Connectivity::Eight, false);  // odd rows, rectangular
    test_crack(Grid2D(20, 33, 1.0, 0.5), Connectivity::Four, true);    // few rows, a contact around the cell
  } else if (mode == "stop") {
    test_stop(64);
  } else {
    std::fprintf(stderr, "usage: mpi_slab_contact operator | surface | solve | traction | coulomb | tresca | free | stress | crack | stop\n");
    return 2;
  }
  const long long failed = mpi::sum(static_cast<long long>(failures));
  if (mpi::is_root())
    std::printf("%s at %d ranks: %s (largest field difference %.2e)\n", mode.c_str(), mpi::size(),
                failed == 0 ? "ok" : "FAILED", worst);
  return failed == 0 ? 0 : 1;
}
