// The thesis' pin-on-disc case (§9.3.2: n = 128, L = 2 mm, 0.5 m at 8 mm/s,
// dt = 0.02 s, h_layer = 1 µm): wall time and contact solves of the explicit
// thesis step and of the adaptive ARKODE integrator.
//
//   build/bench/bench_pin_on_disc --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <omp.h>

#include "wearscale/core/fft.hpp"
#include "wearscale/io/shipped_data.hpp"
#include "wearscale/tribometer/adaptive_wear.hpp"
#include "wearscale/tribometer/pin_on_disc.hpp"

using namespace wearscale;

static void BM_PinOnDiscThesisCase(benchmark::State& state) {
  const bool adaptive = state.range(0) != 0;
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  FFTPlanCache::global().clear();
  FFTPlanCache::global().set_threads(threads);
  const materials::StrengthLaw si(materials::shipped_table("thesis", "Si"));
  const materials::StrengthLaw sio2(materials::shipped_table("thesis", "SiO2"));
  tribometer::PinOnDiscSetup setup;
  setup.on_layer = materials::interface_law("SiO2", sio2, "SiO2", sio2);
  setup.on_substrate = materials::interface_law("SiO2", sio2, "Si", si);
  int solves = 0;
  double mu_last = 0.0;
  for (auto _ : state) {
    tribometer::PinOnDisc model(setup);
    auto observe = [&](const tribometer::PinOnDiscSample& x) { mu_last = x.friction; };
    if (adaptive)
      tribometer::run_adaptive(model, {}, observe);
    else
      model.run(observe);
    solves = model.contact_solves();
  }
  state.counters["contact_solves"] = solves;
  state.counters["mu_final"] = mu_last;
  state.counters["threads"] = threads;
}
BENCHMARK(BM_PinOnDiscThesisCase)
    ->ArgNames({"adaptive", "threads"})
    ->Args({0, 1})->Args({0, 2})->Args({1, 1})->Args({1, 2})
    ->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
