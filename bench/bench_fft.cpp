// The physical floor of a BEM iteration: one r2c + one c2r FFT of the grid.
// Every BEM benchmark is read against these numbers.
//
//   build/bench/bench_fft --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <random>

#include "wearscale/core/fft.hpp"

using namespace wearscale;

static void BM_FFTForwardBackward(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const Grid2D g = Grid2D::square(n, 1.0);
  RealField h(g), back(g);
  std::mt19937 rng(1);
  std::normal_distribution<double> d;
  for (auto& v : h) v = d(rng);
  ComplexField spec = ComplexField::spectrum_of(g);
  auto plan = FFTPlanCache::global().plan(g);
  for (auto _ : state) {
    plan->forward(h, spec);
    plan->backward_unnormalized(spec, back);
    benchmark::DoNotOptimize(back.data());
  }
  state.counters["points"] = static_cast<double>(g.size());
  state.counters["threads"] = plan->threads();
  state.SetItemsProcessed(state.iterations() * static_cast<long>(g.size()));
}
BENCHMARK(BM_FFTForwardBackward)->RangeMultiplier(2)->Range(64, 2048)->Unit(benchmark::kMicrosecond);

static void BM_FFTPlanLookup(benchmark::State& state) {
  FFTPlanCache::global().plan(256, 256);
  for (auto _ : state) benchmark::DoNotOptimize(FFTPlanCache::global().plan(256, 256));
}
BENCHMARK(BM_FFTPlanLookup);
