// The thesis' pin-on-disc case (§9.3.2: n = 128, L = 2 mm, 0.5 m at 8 mm/s,
// dt = 0.02 s, h_layer = 1 µm): wall time, contact solves and BEM iterations
// per solve of the explicit thesis step and of the adaptive ARKODE
// integrator, its stage solves preconditioned by the stage's own
// (K(0) + A)⁻¹ or not, at the stage tolerance (1e-8) or the explicit one (1e-10).
//
//   build/bench/bench_pin_on_disc --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <omp.h>

#include <limits>

#include "wearscale/core/fft.hpp"
#include "wearscale/io/shipped_data.hpp"
#include "wearscale/tribometer/adaptive_wear.hpp"
#include "wearscale/tribometer/pin_on_disc.hpp"

using namespace wearscale;

namespace {
tribometer::PinOnDiscSetup thesis_setup(double layer) {
  const materials::StrengthLaw si(materials::shipped_table("thesis", "Si"));
  const materials::StrengthLaw sio2(materials::shipped_table("thesis", "SiO2"));
  tribometer::PinOnDiscSetup setup;
  setup.on_layer = materials::interface_law("SiO2", sio2, "SiO2", sio2);
  setup.on_substrate = materials::interface_law("SiO2", sio2, "Si", si);
  setup.layer_thickness = layer;
  return setup;
}

void run(benchmark::State& state, const tribometer::PinOnDiscSetup& setup, bool adaptive, int threads) {
  omp_set_num_threads(threads);
  FFTPlanCache::global().set_threads(threads);
  int solves = 0;
  long iterations = 0;
  double mu_last = 0.0;
  for (auto _ : state) {
    tribometer::PinOnDisc model(setup);
    auto observe = [&](const tribometer::PinOnDiscSample& x) { mu_last = x.friction; };
    if (adaptive)
      tribometer::run_adaptive(model, {}, observe);
    else
      model.run(observe);
    solves = model.contact_solves();
    iterations = model.contact_iterations();
  }
  state.counters["contact_solves"] = solves;
  state.counters["iterations_per_solve"] = static_cast<double>(iterations) / solves;
  state.counters["mu_final"] = mu_last;
  state.counters["threads"] = threads;
}
}  // namespace

static void BM_PinOnDiscThesisCase(benchmark::State& state) {
  run(state, thesis_setup(1e-6), state.range(0) != 0, static_cast<int>(state.range(1)));
}
BENCHMARK(BM_PinOnDiscThesisCase)
    ->ArgNames({"adaptive", "threads"})
    ->Args({0, 1})->Args({0, 2})->Args({1, 1})->Args({1, 2})
    ->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

// The adaptive integrator's stage solves: preconditioned (1) or not (0), at
// the stage tolerance 1e-8 (0) or 1e-10 (1), on one thread, for a layer of
// 1 µm and for bulk SiO2 (layer = 0: 1 µm; 1: bulk).
static void BM_PinOnDiscStageSolves(benchmark::State& state) {
  auto setup = thesis_setup(state.range(2) == 0 ? 1e-6 : std::numeric_limits<double>::infinity());
  setup.stage_preconditioner = state.range(0) != 0;
  setup.stage_tolerance = state.range(1) == 0 ? 1e-8 : 1e-10;
  run(state, setup, true, 1);
}
BENCHMARK(BM_PinOnDiscStageSolves)
    ->ArgNames({"preconditioned", "tight", "bulk"})
    ->Args({1, 0, 0})->Args({0, 0, 0})->Args({1, 1, 0})->Args({0, 1, 0})->Args({1, 0, 1})->Args({0, 0, 1})
    ->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
