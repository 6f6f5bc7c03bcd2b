// Polonsky–Keer normal contact on rough surfaces, against its physical floor:
// one iteration needs two convolutions, i.e. two r2c + c2r FFT pairs.
//
//   build/bench/bench_contact --benchmark_counters_tabular=true
//
// Surface (issue #3): H = 0.8, k_l = k_r = 4, k_s = 64, h'_RMS = 1, E* = 1,
// mean pressure 0.03 (about 6.5 % contact), tolerance 1e-10 on the relative
// orthogonality error ε = Σ p|g| / (Σ p · h_rms) (see normal_contact.hpp).
#include <benchmark/benchmark.h>
#include <omp.h>

#include <chrono>

#include "wearscale/bem/normal_contact.hpp"
#include "wearscale/bem/surface_generator.hpp"

using namespace wearscale;
using namespace wearscale::bem;

namespace {
RealField rough(std::size_t n) {
  RoughSurfaceSpec spec;
  spec.grid = Grid2D::square(n, 1.0);
  spec.hurst = 0.8;
  spec.k_l = spec.k_r = 4.0;
  spec.k_s = 64.0;
  spec.seed = 1;
  return generate_surface(spec, RoughnessMeasure::HPrimeRms, 1.0);
}

double fft_pair_seconds(const Grid2D& g) {
  auto plan = FFTPlanCache::global().plan(g);
  RealField a(g), b(g);
  ComplexField s = ComplexField::spectrum_of(g);
  for (std::size_t k = 0; k < a.size(); ++k) a[k] = static_cast<double>(k % 7);
  const int reps = g.size() >= (1u << 22) ? 5 : 20;
  plan->forward(a, s);
  plan->backward_unnormalized(s, b);
  const auto t0 = std::chrono::steady_clock::now();
  for (int r = 0; r < reps; ++r) {
    plan->forward(a, s);
    plan->backward_unnormalized(s, b);
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / reps;
}
}  // namespace

static void BM_RoughContact(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  FFTPlanCache::global().clear();
  FFTPlanCache::global().set_threads(threads);
  const RealField h = rough(n);
  NormalContact contact(h, 1.0);
  const double fft = fft_pair_seconds(h.grid());
  ContactResult r;
  double seconds = 0.0;
  for (auto _ : state) {
    contact.reset();
    const auto t0 = std::chrono::steady_clock::now();
    r = contact.solve_mean_pressure(0.03, {1e-10, 100000});
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    state.SetIterationTime(seconds);
  }
  state.counters["iterations"] = r.iterations;
  state.counters["contact_%"] = 100.0 * r.contact_fraction;
  state.counters["ms_per_iter"] = 1e3 * seconds / r.iterations;
  state.counters["fft_pair_ms"] = 1e3 * fft;
  state.counters["iter/fft_pair"] = seconds / r.iterations / fft;
  state.counters["threads"] = threads;
}
BENCHMARK(BM_RoughContact)
    ->Args({512, 1})->Args({512, 2})->Args({1024, 1})->Args({1024, 2})->Args({2048, 1})->Args({2048, 2})
    ->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);
