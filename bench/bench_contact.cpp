// Normal contact on rough surfaces, four solvers side by side in one run:
//   method 0: NormalContact preconditioned by S: u = K p (one FFT pair),
//             z = S r (one pair), t·Kt by Parseval (one r2c): 2.5 pairs;
//   method 1: NormalContact, unpreconditioned Polonsky–Keer: 1.5 pairs;
//   method 2: a textbook Polonsky–Keer (polonsky_keer_reference.hpp): u = K p
//             and r = K t, two pairs;
//   method 3: NormalContact preconditioned by the two-level (the default):
//             z = M r by one pair of a quarter of the points, ≈ 1.73 pairs.
// iter/fft_pair is the time of one iteration over that of one r2c + c2r pair.
//
//   build/bench/bench_contact --benchmark_filter=BM_RoughContact --benchmark_counters_tabular=true
//
// BM_IterationFloor: the operator work one iteration of each method cannot
// do without, on fixed fields and without the solver's passes: u = K p and
// t·Kt (Polonsky–Keer's 1.5 pairs of transforms, with the operator's own
// spectral multiplies), and with z = M r by the two-level (part 1) or z = S r
// (part 2) added. Its iter/fft_pair is the floor of the solvers' figure
// above; the difference is the passes over the fields.
//
// BM_ContactLoadRamp: the same surface at 512² and 2048² loaded in ten steps
// of +0.1 % or +1 % from p̄ = 0.03 (warm starts, as the wear maps do), with S or
// the two-level, with or without the load predictor: iterations per step.
//
// BM_FrictionalRoughSphere: the frictional solver (Appendix A) on the rough
// sphere of Fig. A.5 on 512² points: L = 500 µm, R = 6 mm, E = 70 GPa,
// ν = 0.17 (coupled), Sa = 0.01 µm, H = 0.8, λ_l = λ_r = 10 µm (k = 50),
// λ_s = 1.95 µm (k_s = 256, the Nyquist wavenumber; 1.37 µm in the thesis at
// 729²), p_N,0 = 10 MPa, p_x,0 = 2 MPa; Tresca σ_m,T = 250 MPa (case 0, as in
// Fig. A.5) or Coulomb μ = 0.5 (case 1); tolerance 1e-10 on the cost (A.14).
// Four cases (see kFrictionalCases) on 256², 512² and 729² (Fig. A.5's grid),
// each with the plain lagged bound (anderson 0) and Anderson's mixing of the
// bound updates (anderson 1) side by side; the counters give the answer
// (contact, slip, max ‖p_T‖, energy) besides iterations and CPU seconds.
//
//   OMP_NUM_THREADS=1 build/bench/bench_contact --benchmark_filter=Frictional --benchmark_counters_tabular=true
// One iteration needs 9 FFTs: u = F * p (3 r2c + 3 c2r) and the spectra of
// the search direction (3 r2c), i.e. 4.5 FFT pairs.
//
// Surface: H = 0.8, k_l = k_r = 4, k_s = 64, h'_RMS = 1, E* = 1,
// mean pressure 0.03 (about 6.5 % contact), tolerance 1e-10 on the relative
// orthogonality error ε = Σ p|g| / (Σ p · h_rms) (see normal_contact.hpp).
#include <cmath>
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <ctime>

#include "wearscale/bem/frictional_contact.hpp"
#include "wearscale/bem/normal_contact.hpp"
#include "wearscale/bem/surface_generator.hpp"
#include "polonsky_keer_reference.hpp"

using namespace wearscale;
using namespace wearscale::bem;

namespace {
// Process CPU time: on a shared machine the one-thread figures that do not
// depend on how many other processes compete for the cores.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

RealField rough(std::size_t n) {
  RoughSurfaceSpec spec;
  spec.grid = Grid2D::square(n, 1.0);
  spec.hurst = 0.8;
  spec.k_l = spec.k_r = 4.0;
  spec.k_s = 64.0;
  spec.seed = 1;
  return generate_surface(spec, RoughnessMeasure::HPrimeRms, 1.0);
}

double fft_pair_seconds(const Grid2D& g, bool cpu = false) {
  auto plan = FFTPlanCache::global().plan(g);
  RealField a(g), b(g);
  ComplexField s = ComplexField::spectrum_of(g);
  for (std::size_t k = 0; k < a.size(); ++k) a[k] = static_cast<double>(k % 7);
  const int reps = g.size() >= (1u << 22) ? 5 : 20;
  plan->forward(a, s);
  plan->backward_unnormalized(s, b);
  const auto t0 = std::chrono::steady_clock::now();
  const double c0 = cpu_seconds();
  for (int r = 0; r < reps; ++r) {
    plan->forward(a, s);
    plan->backward_unnormalized(s, b);
  }
  if (cpu) return (cpu_seconds() - c0) / reps;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / reps;
}

// The solver's method for a benchmark's code (0: S, 1: unpreconditioned, 3:
// two-level); the two-level's coarse plan is made here, before the clock starts.
ContactMethod bench_method(int code, std::size_t n) {
  if (code == 3) FFTPlanCache::global().plan(n / 2, n / 2);
  return code == 0 ? ContactMethod::PreconditionedCG
         : code == 3 ? ContactMethod::TwoLevelCG
                     : ContactMethod::PolonskyKeer;
}
}  // namespace

static void BM_RoughContact(benchmark::State& state) {
  const int method = static_cast<int>(state.range(0));
  const auto n = static_cast<std::size_t>(state.range(1));
  const int threads = static_cast<int>(state.range(2));
  omp_set_num_threads(threads);
  FFTPlanCache::global().clear();
  FFTPlanCache::global().set_threads(threads);
  const RealField h = rough(n);
  NormalContact contact(h, 1.0);
  const double fft = fft_pair_seconds(h.grid()), fft_cpu = fft_pair_seconds(h.grid(), true);
  const ContactMethod solver = bench_method(method, n);
  int iterations = 0;
  double seconds = 0.0, cpu = 0.0, fraction = 0.0;
  for (auto _ : state) {
    contact.reset();
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = cpu_seconds();
    if (method == 2) {
      const auto r = bench::polonsky_keer_reference(h, 1.0, 0.03, 1e-10, 100000);
      iterations = r.iterations;
      fraction = r.contact_fraction;
    } else {
      ContactOptions o{1e-10, 100000, solver};
      const auto r = contact.solve_mean_pressure(0.03, o);
      iterations = r.iterations;
      fraction = r.contact_fraction;
    }
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    cpu = cpu_seconds() - c0;
    state.SetIterationTime(seconds);
  }
  state.counters["iterations"] = iterations;
  state.counters["contact_%"] = 100.0 * fraction;
  state.counters["ms_per_iter"] = 1e3 * seconds / iterations;
  state.counters["fft_pair_ms"] = 1e3 * fft;
  state.counters["iter/fft_pair"] = seconds / iterations / fft;
  state.counters["cpu_s"] = cpu;  // one thread: the time without the other processes' share
  state.counters["cpu_iter/fft_pair"] = cpu / iterations / fft_cpu;
  state.counters["threads"] = threads;
}
BENCHMARK(BM_RoughContact)
    ->ArgNames({"method", "n", "threads"})
    ->ArgsProduct({{0, 1, 2, 3}, {512, 1024, 2048, 4096}, {1}})
    ->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);

static void BM_IterationFloor(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const int part = static_cast<int>(state.range(1));
  omp_set_num_threads(1);
  FFTPlanCache::global().clear();
  FFTPlanCache::global().set_threads(1);
  const RealField h = rough(n);
  HalfSpaceNormal body(h.grid(), 1.0, Boundary::Periodic);
  RealField p(h.grid()), u(h.grid()), t(h.grid()), z(h.grid());
  for (std::size_t k = 0; k < h.size(); ++k) {  // supported where the surface is high, as a contact is
    p[k] = std::max(h[k] - 1.5, 0.0);
    t[k] = p[k] > 0.0 ? h[k] - 2.0 : 0.0;
  }
  const double fft = fft_pair_seconds(h.grid());
  if (part == 1) body.two_level_stiffness(t, z);  // made (and its coarse plan) before the clock
  double form = 0.0, seconds = 0.0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    body.displacement(p, u, 1.0);
    form += body.form(t);
    if (part == 1) body.two_level_stiffness(t, z);
    if (part == 2) body.stiffness(t, z);
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    state.SetIterationTime(dt);
    seconds += dt;
  }
  benchmark::DoNotOptimize(form);
  state.counters["fft_pair_ms"] = 1e3 * fft;
  state.counters["iter/fft_pair"] = seconds / static_cast<double>(state.iterations()) / fft;
}
BENCHMARK(BM_IterationFloor)
    ->ArgNames({"n", "part"})
    ->ArgsProduct({{512, 1024, 2048, 4096}, {0, 1, 2}})
    ->UseManualTime()->Unit(benchmark::kMillisecond);

// A load ramp on one surface (warm starts, as a wear map walks its loads):
// ten steps of `step` hundredths of a per cent from p̄ = 0.03, the iterations
// and time of the steps alone (the first, cold solve is not timed).
static void BM_ContactLoadRamp(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const int method = static_cast<int>(state.range(1));
  const bool predict = state.range(2) != 0;
  const double step = 1e-4 * static_cast<double>(state.range(3));
  omp_set_num_threads(1);
  FFTPlanCache::global().clear();
  FFTPlanCache::global().set_threads(1);
  const RealField h = rough(n);
  NormalContact contact(h, 1.0);
  const double fft = fft_pair_seconds(h.grid());
  ContactOptions o{1e-10, 100000, bench_method(method, n)};
  o.predict_load = predict;
  const int steps = 10;
  double total = 0.0, worst = 0.0, seconds = 0.0;
  for (auto _ : state) {
    contact.reset();
    contact.solve_mean_pressure(0.03, o);
    const auto t0 = std::chrono::steady_clock::now();
    total = worst = 0.0;
    for (int k = 1; k <= steps; ++k) {
      const int it = contact.solve_mean_pressure(0.03 * std::pow(1.0 + step, k), o).iterations;
      total += it;
      worst = std::max(worst, static_cast<double>(it));
    }
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    state.SetIterationTime(seconds);
  }
  state.counters["iterations_per_step"] = total / steps;
  state.counters["worst_step"] = worst;
  state.counters["ms_per_iter"] = 1e3 * seconds / total;
  state.counters["iter/fft_pair"] = seconds / total / fft;
}
BENCHMARK(BM_ContactLoadRamp)
    ->ArgNames({"n", "method", "predict", "step_bp"})
    ->ArgsProduct({{512, 2048}, {0, 3}, {0, 1}, {10, 100}})
    ->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);

// The four rough cases (`case` argument): 0 the Fig. A.5 sphere with Tresca;
// 1 the same with Coulomb μ = 0.5; 2 Coulomb μ = 0.5 with ν = 0.3 on the
// surface of seed 2; 3 Tresca with ⟨p_x⟩ = 4 MPa on the surface of seed 3.
// Case 4, the sphere of case 0 without friction (μ = 0, ⟨p_x⟩ = 0), is the
// normal solve alone: the iterations no treatment of the friction bound
// can go below.
struct FrictionalCase {
  bool tresca;
  double poisson;
  int seed;
  double p_x;
};
constexpr FrictionalCase kFrictionalCases[] = {
    {true, 0.17, 1, 2e6}, {false, 0.17, 1, 2e6}, {false, 0.3, 2, 2e6}, {true, 0.17, 3, 4e6}, {false, 0.17, 1, 0.0}};

static void BM_FrictionalRoughSphere(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const FrictionalCase c = kFrictionalCases[state.range(1)];
  const int threads = static_cast<int>(state.range(2));
  FrictionalOptions options{1e-10, 100000};
  options.outer_acceleration = state.range(3) == 1 ? OuterAcceleration::Anderson : OuterAcceleration::None;
  omp_set_num_threads(threads);
  FFTPlanCache::global().clear();
  FFTPlanCache::global().set_threads(threads);
  const double l = 500e-6;
  RoughSurfaceSpec spec;
  spec.grid = Grid2D::square(n, l);
  spec.hurst = 0.8;
  spec.k_l = spec.k_r = 50.0;
  spec.k_s = static_cast<double>(n / 2);
  spec.seed = static_cast<std::uint64_t>(c.seed);
  const RealField h = add(generate_surface(spec, RoughnessMeasure::Sa, 0.01e-6), sphere(spec.grid, 6e-3, l / 2, l / 2));
  const double mu = c.p_x > 0.0 ? 0.5 : 0.0;
  FrictionalContact contact(h, 70e9, c.poisson, c.tresca ? FrictionLaw::tresca(250e6) : FrictionLaw::coulomb(mu));
  const double fft = fft_pair_seconds(h.grid());
  FrictionalResult r;
  double seconds = 0.0, cpu = 0.0;
  for (auto _ : state) {
    contact.reset();
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = cpu_seconds();
    r = contact.solve({10e6, c.p_x, 0.0}, options);
    cpu = cpu_seconds() - c0;
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    state.SetIterationTime(seconds);
  }
  double max_traction = 0.0;
  for (std::size_t k = 0; k < h.size(); ++k)
    max_traction = std::max(max_traction, std::hypot(contact.traction().x[k], contact.traction().y[k]));
  state.counters["iterations"] = r.iterations;
  state.counters["bound_updates"] = r.bound_updates;
  state.counters["mixed_updates"] = r.accelerated_updates;
  state.counters["unsettled"] = static_cast<double>(r.unsettled_points);
  state.counters["contact_%"] = 100.0 * r.contact_fraction;
  state.counters["slip_%"] = 100.0 * r.slip_fraction;
  state.counters["stick_%_of_contact"] = 100.0 * r.stick_fraction / r.contact_fraction;
  state.counters["p_x_mean"] = r.mean_traction.x;
  state.counters["max_p_T"] = max_traction;
  state.counters["energy_pJ"] = 1e12 * r.elastic_energy;
  state.counters["cpu_s"] = cpu;
  state.counters["ms_per_iter"] = 1e3 * seconds / r.iterations;
  state.counters["iter/fft_pair"] = seconds / r.iterations / fft;
  state.counters["threads"] = threads;
}
// anderson 0: the plain lagged bound (OuterAcceleration::None); 1: Anderson's mixing (the default).
BENCHMARK(BM_FrictionalRoughSphere)
    ->ArgNames({"n", "case", "threads", "anderson"})
    ->ArgsProduct({{512}, {0, 1, 2, 3}, {1}, {0, 1}})
    ->ArgsProduct({{256}, {0, 1, 2, 3}, {1}, {0, 1}})
    ->Args({256, 4, 1, 0})->Args({512, 4, 1, 0})->Args({729, 4, 1, 0})
    ->Args({512, 0, 2, 0})->Args({512, 1, 2, 0})
    ->Args({729, 0, 1, 0})->Args({729, 0, 1, 1})
    ->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);
